// Minnaert, per pixel (book §5.7.2, §7.4): D (max(0,N.V) max(0,N.L))^k max(0,N.L), k = m - 1 (E5, E10), normal renormalised.
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float  MinnaertPower : register(c9);   // k = m - 1

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    // Each dot clamped before the product: pow of a negative product is NaN (E10).
    float VdotN = max(0.0f, dot(PixelToEye, N));
    float Irradiance = max(0.0f, dot(LightVector, N));
    return float4(DiffuseColor * pow(VdotN * Irradiance, MinnaertPower) * Irradiance, 1.0f);
}
