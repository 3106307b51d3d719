// Cook-Torrance, robust per pixel (book §5.8.3, §7.7): the facet angle from atan2(|N x H|, N.H), accurate as m -> 0.
float3 LightVector     : register(c4);
float3 EyePosition     : register(c5);
float3 DiffuseColor    : register(c7);   // the overall colour
float3 RoughnessParams : register(c9);   // (c, m, R0)

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 V = normalize(EyePosition - In.InterPos);
    float NdotL = dot(N, LightVector);
    float NdotV = dot(N, V);

    float Reflectance = 0.0f;
    if (NdotL > 0.0f && NdotV > 0.0f)   // upper hemisphere only (E6)
    {
        float3 H = normalize(LightVector + V);
        float NdotH = max(0.0f, dot(N, H));
        float VdotH = dot(V, H);
        // |N x H| keeps the small angles sqrt(1 - (N.H)^2) loses to cancellation.
        float Angle = atan2(length(cross(N, H)), NdotH);
        float Slope = Angle / RoughnessParams.y;
        float D = RoughnessParams.x * exp(-Slope * Slope);
        float G = saturate(2.0f * NdotH * min(NdotV, NdotL) / VdotH);   // over V.H (E6)
        float f = 1.0f - VdotH;
        float F = RoughnessParams.z + (1.0f - RoughnessParams.z) * f * f * f * f * f;   // Schlick in V.H (E6)
        Reflectance = F * D * G / NdotL / NdotV;   // one dot at a time: no underflow of the product
    }
    return float4(DiffuseColor * Reflectance, 1.0f);
}
