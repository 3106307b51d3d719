// Minnaert, per pixel (book §5.7.2, §7.4), MUTANT: the dots are multiplied before clamping (the book's form, errata E10), so where N.L < 0 < N.V pow() gets a negative base and returns NaN; the later max(0, N.L) = 0 cannot cancel it (NaN * 0 = NaN).
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
    float Irradiance = max(0.0f, dot(LightVector, N));
    float Product = dot(PixelToEye, N) * dot(LightVector, N);   // planted bug: neither dot clamped
    return float4(DiffuseColor * pow(Product, MinnaertPower) * Irradiance, 1.0f);
}
