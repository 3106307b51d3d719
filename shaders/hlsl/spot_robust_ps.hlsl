// Spotlight, robust per pixel (book §2.4, errata E1): no 0/0 when the light sits on the surface point (d = 0).
float3 LightVector   : register(c4);    // the negated spot axis
float3 LightPosition : register(c6);
float3 DiffuseColor  : register(c7);
float3 LightColor    : register(c9);    // I
float3 Attenuation   : register(c10);   // (A, B, C)
float3 SpotParams    : register(c11);   // (cos umbra, cos penumbra, falloff)

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float SpotFactor(float CosTheta)
{
    if (CosTheta >= SpotParams.x)
        return 1.0f;
    if (CosTheta <= SpotParams.y)
        return 0.0f;
    return pow((CosTheta - SpotParams.y) / (SpotParams.x - SpotParams.y), SpotParams.z);   // E1
}

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToLight = LightPosition - In.InterPos;
    float Distance = length(PixelToLight);
    // d = 0: direction, cone angle and falloff undefined; no light instead of NaN.
    float3 Color = 0.0f;
    if (Distance > 0.0f)
    {
        float3 L = PixelToLight / Distance;
        float Lit = SpotFactor(dot(L, LightVector)) * max(0.0f, dot(N, L));
        if (Lit > 0.0f)
            Color = DiffuseColor * LightColor *
                    (Lit / (Attenuation.x * Distance * Distance + Attenuation.y * Distance + Attenuation.z));
    }
    return float4(Color, 1.0f);
}
