// Spotlight, per pixel (book §2.4): umbra, penumbra and falloff over an attenuated point light (E1), normal renormalised.
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

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToLight = LightPosition - In.InterPos;
    float Distance = length(PixelToLight);
    float3 LightDirection = normalize(PixelToLight);
    float Falloff = Attenuation.x * Distance * Distance + Attenuation.y * Distance + Attenuation.z;

    // 1 inside the umbra, 0 outside the penumbra, a ramp rising toward the umbra between (E1).
    float CosTheta = dot(LightDirection, LightVector);
    float Spot;
    if (CosTheta >= SpotParams.x)
        Spot = 1.0f;
    else if (CosTheta <= SpotParams.y)
        Spot = 0.0f;
    else
        Spot = pow((CosTheta - SpotParams.y) / (SpotParams.x - SpotParams.y), SpotParams.z);

    return float4(DiffuseColor * LightColor * Spot * max(0.0f, dot(N, LightDirection)) / Falloff, 1.0f);
}
