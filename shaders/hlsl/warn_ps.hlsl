// Warn spotlight, per pixel (book §1.6, §6.3.1 Diffuse_Warn_PS20): the VS's equation with the Lambert term clamped too (E11), normal renormalised.
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
    float3 LightDirection = normalize(PixelToLight);
    float3 Intensity = LightColor / dot(PixelToLight, PixelToLight);   // inverse square
    // Clamped before pow: a negative base is NaN (E11).
    float Warn = pow(max(0.0f, dot(LightDirection, LightVector)), WarnExponent);
    return float4(DiffuseColor * Intensity * Warn * max(0.0f, dot(N, LightDirection)), 1.0f);
}
