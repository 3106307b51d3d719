// Cook-Torrance, per vertex (book §5.8.3, §7.7 CookTorrance_VS): D F G / ((N.L)(N.V)) with G over V.H and Schlick's Fresnel in V.H (E6, E9).
matrix Transform       : register(c0);
float3 LightVector     : register(c4);   // object space, unit, toward the light
float3 EyePosition     : register(c5);   // object space
float3 DiffuseColor    : register(c7);   // the overall colour: there is no separate Lambert term
float3 RoughnessParams : register(c9);   // (c, m, R0): Gaussian constant, slope, Fresnel at normal incidence

struct VS_INPUT
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 Diffuse  : COLOR0;
};

VS_OUTPUT main(const VS_INPUT InVertex)
{
    VS_OUTPUT OutVertex;
    float3 N = InVertex.Normal;
    float3 VertexToEye = normalize(EyePosition - InVertex.Position.xyz);
    float3 HalfVector  = normalize(LightVector + VertexToEye);
    float NdotL = dot(N, LightVector);
    float NdotV = dot(N, VertexToEye);

    // Zero off the upper hemisphere: the final division by (N.L)(N.V) is unguarded otherwise (E6).
    float Reflectance = 0.0f;
    if (NdotL > 0.0f && NdotV > 0.0f)
    {
        float NdotH = max(0.0f, dot(N, HalfVector));
        float VdotH = dot(VertexToEye, HalfVector);
        // a = acos(N.H) as atan2(sqrt(1 - x^2), x), the same angle: the driver's acos is off by up
        // to 1.6e-4 rad on Mesa, its atan2 by ~3e-6. x clamped to 1 as E9 asks (N.H >= 0 already).
        float CosAlpha = min(NdotH, 1.0f);
        float Alpha = atan2(sqrt((1.0f - CosAlpha) * (1.0f + CosAlpha)), CosAlpha);
        float Slope = Alpha / RoughnessParams.y;
        float D = RoughnessParams.x * exp(-Slope * Slope);
        // Divided by V.H, not the book's N.H (E6).
        float G = max(0.0f, min(1.0f, min(2.0f * NdotH * NdotV / VdotH, 2.0f * NdotH * NdotL / VdotH)));
        // Schlick's Fresnel in V.H (E6); the fifth power by multiplication, as pow of a
        // slightly negative 1 - V.H would be NaN.
        float OneMinusVdotH = 1.0f - VdotH;
        float Power2 = OneMinusVdotH * OneMinusVdotH;
        float F = RoughnessParams.z + (1.0f - RoughnessParams.z) * Power2 * Power2 * OneMinusVdotH;
        Reflectance = F * D * G / (NdotL * NdotV);
    }

    OutVertex.Diffuse  = DiffuseColor * Reflectance;
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
