// Lambert diffuse, per pixel (book §5.5, §7.1.2), MUTANT: LightVector is declared at register c5, where the test bed (as the book's) puts the eye position; the shader lights with the unnormalised object-space eye position instead of the light vector.
float3 LightVector  : register(c5);   // planted bug: c4 is the light vector
float3 DiffuseColor : register(c7);

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    return float4(DiffuseColor * max(0.0f, dot(LightVector, N)), 1.0f);
}
