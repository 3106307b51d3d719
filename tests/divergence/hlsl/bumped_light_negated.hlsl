// Lambert with a tangent-space normal map and an ambient term (book §5.5, §2.5), ported to HLSL SM5 with Texture2D and SamplerState; planted bug (light_negated): the light vector negated (the direction the light travels, not toward the light).
cbuffer PerDraw
{
    float4x4 mvp;
    float3   lightVec;
    float    pad0;
    float3   surfaceColour;
    float    pad1;
    float3   ambient;
};

Texture2D    bumpTexture : register(t0);
SamplerState bumpSampler : register(s0);

struct VSIn
{
    float4 pos     : POSITION;
    float3 normal  : NORMAL;
    float3 tangent : TANGENT;
    float2 uv      : TEXCOORD0;
};

struct VSOut
{
    float4 pos     : SV_Position;
    float3 normal  : TEXCOORD0;
    float3 tangent : TEXCOORD1;
    float2 uv      : TEXCOORD2;
};

VSOut BumpVS(VSIn vin)
{
    VSOut vout;
    vout.pos = mul(mvp, vin.pos);
    vout.normal = vin.normal;
    vout.tangent = vin.tangent;
    vout.uv = vin.uv;
    return vout;
}

float4 BumpPS(VSOut pin) : SV_Target
{
    float3 n = normalize(pin.normal);
    float3 t = normalize(pin.tangent - dot(n, pin.tangent) * n);
    float3 b = cross(n, t);
    float3 texel = bumpTexture.Sample(bumpSampler, pin.uv).rgb;
    float3 m = 2.0 * texel - 1.0;
    float3 nb = normalize(m.x * t + m.y * b + m.z * n);
    float d = saturate(dot(nb, -lightVec));
    return float4(surfaceColour * ambient + surfaceColour * d, 1.0);
}
