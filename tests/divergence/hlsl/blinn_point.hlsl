// Blinn-Phong lit by a point light with inverse-square falloff, plus an ambient floor (book §2.1.2, §5.6.3), HLSL SM5 style: the original.
cbuffer PerObject
{
    float4x4 WorldViewProj;
    float3   LightPosition;     // object space
    float    LightPower;        // intensity at unit distance
    float3   EyePosition;       // object space
    float    Shininess;
};

cbuffer PerMaterial
{
    float3 Albedo;
    float  Ambient;
    float3 SpecularTint;
};

struct VSInput
{
    float4 position : POSITION;
    float3 normal   : NORMAL;
};

struct PSInput
{
    float4 clip    : SV_Position;
    float3 normal  : TEXCOORD0;
    float3 toLight : TEXCOORD1;
    float3 toEye   : TEXCOORD2;
};

PSInput BlinnPointVS(VSInput vin)
{
    PSInput vout;
    vout.clip = mul(WorldViewProj, vin.position);
    vout.normal = vin.normal;
    vout.toLight = LightPosition - vin.position.xyz;
    vout.toEye = EyePosition - vin.position.xyz;
    return vout;
}

float4 BlinnPointPS(PSInput pin) : SV_Target
{
    float3 N = normalize(pin.normal);
    float distSq = dot(pin.toLight, pin.toLight);
    float3 L = normalize(pin.toLight);
    float3 V = normalize(pin.toEye);
    float3 H = normalize(L + V);
    float falloff = LightPower / distSq;
    float diffuse = saturate(dot(N, L));
    float NdotH = saturate(dot(N, H));
    float specular = diffuse > 0 ? pow(NdotH, Shininess) : 0;
    float3 lit = (Albedo * diffuse + SpecularTint * specular) * falloff;
    return float4(lit + Albedo * Ambient, 1.0);
}
