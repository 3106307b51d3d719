// Point light with generalised attenuation, per pixel (book §2.1, §2.3.2): D I max(0,N.Lp) / (A d^2 + B d + C), normal renormalised.
float3 LightPosition : register(c6);
float3 DiffuseColor  : register(c7);
float3 LightColor    : register(c9);    // I
float3 Attenuation   : register(c10);   // (A, B, C)

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToLight = LightPosition - In.InterPos;
    float Distance = length(PixelToLight);
    float3 LightDirection = normalize(PixelToLight);
    float Falloff = Attenuation.x * Distance * Distance + Attenuation.y * Distance + Attenuation.z;
    return float4(DiffuseColor * LightColor * max(0.0f, dot(N, LightDirection)) / Falloff, 1.0f);
}
