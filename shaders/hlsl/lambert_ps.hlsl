// Lambert diffuse, per pixel (book §5.5, §7.1.2): the interpolated normal is renormalised before N.L.
float3 LightVector  : register(c4);
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
