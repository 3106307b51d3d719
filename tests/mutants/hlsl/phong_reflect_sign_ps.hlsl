// Phong, per pixel (book §5.6.2), MUTANT: the reflection vector's sign is flipped, so the highlight lands on the wrong side.
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float4 SpecularColor : register(c8);

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    float3 Reflection = -normalize(2.0f * N * dot(N, LightVector) - LightVector);   // planted bug
    float3 Diffuse  = DiffuseColor * max(0.0f, dot(LightVector, N));
    float3 Specular = SpecularColor.rgb * pow(max(dot(Reflection, PixelToEye), 0.0f), SpecularColor.w);
    return float4(Diffuse + Specular, 1.0f);
}
