// Oren-Nayar, per pixel with the angle LUT (book §7.3 OrenNayar_PS, Fill_OrenNayar_Texture): sin(alpha) tan(beta) read from a 2D texture (E8).
float3  LightVector      : register(c4);
float3  EyePosition      : register(c5);
float3  DiffuseColor     : register(c7);
float   RoughnessSquared : register(c9);   // sigma^2
sampler AngleTex         : register(s0);   // R32F, u = N.V, v = N.L, both mapped from [-1, 1]

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    float2 DotProducts = float2(dot(PixelToEye, N), dot(LightVector, N));   // (N.V, N.L)
    float Irradiance = max(0.0f, DotProducts.y);

    // cos C from the tangent-plane projections; 0 where a projection vanishes (E8).
    float3 ViewProjected  = PixelToEye - N * DotProducts.x;
    float3 LightProjected = LightVector - N * DotProducts.y;
    float CosC = 0.0f;
    if (dot(ViewProjected, ViewProjected) >= 1e-12f && dot(LightProjected, LightProjected) >= 1e-12f)
        CosC = max(0.0f, dot(normalize(ViewProjected), normalize(LightProjected)));

    // The inverse of the fill's 2u - 1: [-1, 1] dots to [0, 1] texture coordinates.
    float AngleTerm = tex2D(AngleTex, 0.5f * DotProducts + 0.5f).x;

    float A = 1.0f - 0.5f * RoughnessSquared / (RoughnessSquared + 0.33f);
    float B = 0.45f * RoughnessSquared / (RoughnessSquared + 0.09f);

    return float4(DiffuseColor * Irradiance * (A + B * CosC * AngleTerm), 1.0f);
}
