// Point light with attenuation, robust per pixel (book §2.1, §2.3.2): no 0/0 when the light sits on the surface point (d = 0).
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
    // d = 0: direction and falloff undefined; no light instead of NaN.
    float Lambert = Distance > 0.0f ? max(0.0f, dot(N, PixelToLight / Distance)) : 0.0f;
    float3 Color = 0.0f;
    if (Lambert > 0.0f)
        Color = DiffuseColor * LightColor *
                (Lambert / (Attenuation.x * Distance * Distance + Attenuation.y * Distance + Attenuation.z));
    return float4(Color, 1.0f);
}
