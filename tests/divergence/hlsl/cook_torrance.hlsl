// Cook-Torrance: Beckmann distribution, V-cavity masking-shadowing and Schlick's Fresnel over a Lambert base (book §5.8.3), HLSL SM5 style: the original.
cbuffer Frame
{
    float4x4 WorldViewProj;
    float3   EyePosition;       // object space
    float    Roughness;         // Beckmann m, the rms microfacet slope
    float3   LightDirection;    // object space, unit, toward the light
    float    SpecularWeight;
    float3   BaseColour;
};

struct VSInput
{
    float4 position : POSITION;
    float3 normal   : NORMAL;
};

struct PSInput
{
    float4 clip   : SV_Position;
    float3 normal : TEXCOORD0;
    float3 toEye  : TEXCOORD1;
};

PSInput CookTorranceVS(VSInput vin)
{
    PSInput vout;
    vout.clip = mul(WorldViewProj, vin.position);
    vout.normal = vin.normal;
    vout.toEye = EyePosition - vin.position.xyz;
    return vout;
}

float4 CookTorrancePS(PSInput pin) : SV_Target
{
    float3 N = normalize(pin.normal);
    float3 V = normalize(pin.toEye);
    float3 L = LightDirection;
    float3 H = normalize(L + V);
    float NdotL = saturate(dot(N, L));
    float NdotV = saturate(dot(N, V));
    float NdotH = max(dot(N, H), 1e-4);
    float VdotH = saturate(dot(V, H));
    float m2 = Roughness * Roughness;
    float c2 = NdotH * NdotH;
    float D = exp((c2 - 1.0) / (m2 * c2)) / (m2 * c2 * c2);
    float G = min(1.0, min(2.0 * NdotH * NdotV / VdotH, 2.0 * NdotH * NdotL / VdotH));
    float F = 0.04 + 0.96 * pow(1.0 - VdotH, 5.0);
    float specular = D * G * F / max(4.0 * NdotL * NdotV, 1e-4);
    float3 colour = (BaseColour + SpecularWeight * specular) * NdotL;
    return float4(colour, 1.0);
}
