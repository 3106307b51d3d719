// Warn spotlight, per pixel with the power LUT (book §6.3.3): max(0,Lp.L)^a read from a 2D texture, one row per exponent (E11).
float3  LightVector   : register(c4);    // the negated spot axis
float3  LightPosition : register(c6);
float3  DiffuseColor  : register(c7);
float3  LightColor    : register(c9);    // I
float   WarnExponent  : register(c10);   // a: selects the row
float   PowerLutRows  : register(c11);   // the LUT's height: row j holds exponent j
sampler PowerTex      : register(s0);    // R32F, texel (i, j) = ((i + 0.5)/width)^j

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToLight = LightPosition - In.InterPos;
    float3 LightDirection = normalize(PixelToLight);
    float3 Intensity = LightColor / dot(PixelToLight, PixelToLight);   // inverse square
    // u: the clamped cone cosine (E11); v: the centre of row a, so rows are not blended.
    float2 WarnLookUp = float2(max(0.0f, dot(LightDirection, LightVector)), (WarnExponent + 0.5f) / PowerLutRows);
    float Warn = tex2D(PowerTex, WarnLookUp).x;
    return float4(DiffuseColor * Intensity * Warn * max(0.0f, dot(N, LightDirection)), 1.0f);
}
