// Phong, per pixel, literal power (book §5.6.2, §7.2.1 Phong_PS, §7.6): phong_ps.hlsl with the power a literal 7, as the book's Phong_PS: 21 vs 37 slots.
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float3 SpecularColor : register(c8);   // rgb only: the power is the literal below

static const float SpecularPower = 7.0f;   // the case's default power; --param power does not reach it

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    float3 Reflection = normalize(2.0f * N * dot(N, LightVector) - LightVector);
    float3 Diffuse  = DiffuseColor * max(0.0f, dot(LightVector, N));
    float3 Specular = SpecularColor * pow(max(dot(Reflection, PixelToEye), 0.0f), SpecularPower);
    return float4(Diffuse + Specular, 1.0f);
}
