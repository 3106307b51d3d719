// Warn spotlight, robust per pixel (book §1.6, §6.3.1, errata E11): no 0 * inf when the light sits on the surface point (d = 0).
float3 LightVector   : register(c4);    // the negated spot axis
float3 LightPosition : register(c6);
float3 DiffuseColor  : register(c7);
float3 LightColor    : register(c9);    // I
float  WarnExponent  : register(c10);   // a

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToLight = LightPosition - In.InterPos;
    float DistanceSquared = dot(PixelToLight, PixelToLight);
    // d = 0: direction and 1/d^2 undefined; no light instead of NaN.
    float3 Color = 0.0f;
    if (DistanceSquared > 0.0f)
    {
        float3 L = PixelToLight * rsqrt(DistanceSquared);
        float Lit = pow(max(0.0f, dot(L, LightVector)), WarnExponent) * max(0.0f, dot(N, L));   // E11
        if (Lit > 0.0f)
            Color = DiffuseColor * LightColor * (Lit / DistanceSquared);
    }
    return float4(Color, 1.0f);
}
