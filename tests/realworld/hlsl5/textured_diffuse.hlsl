// Lambert diffuse per pixel times a texture (book §5.5, §7.1.2: D * max(0, N.L)), written as a D3D11 tutorial writes it: SM5 cbuffers, row-vector matrices, Texture2D + SamplerState, both stages in one file.
cbuffer MatrixBuffer
{
    matrix worldMatrix;
    matrix viewMatrix;
    matrix projectionMatrix;
};

cbuffer LightBuffer
{
    float4 diffuseColor;
    float3 lightDirection;     // the direction the light travels, in world space
    float padding;             // keeps the buffer a multiple of 16 bytes
};

Texture2D shaderTexture : register(t0);
SamplerState SampleType : register(s0);

struct AppVertex
{
    float4 position : POSITION;
    float3 normal : NORMAL;
    float2 uv : TEXCOORD0;
};

struct Interpolants
{
    float4 clipPosition : SV_POSITION;
    float3 worldNormal : NORMAL;
    float2 uv : TEXCOORD0;
};

Interpolants TexturedDiffuseVS(AppVertex vin)
{
    Interpolants vout;
    float4 p = float4(vin.position.xyz, 1.0f);
    p = mul(p, worldMatrix);
    p = mul(p, viewMatrix);
    vout.clipPosition = mul(p, projectionMatrix);
    // The world matrix has no scale, so its upper 3x3 carries normals unchanged in length.
    vout.worldNormal = mul(vin.normal, (float3x3)worldMatrix);
    vout.uv = vin.uv;
    return vout;
}

float4 TexturedDiffusePS(Interpolants pin) : SV_TARGET
{
    float3 n = normalize(pin.worldNormal);
    float3 toLight = -lightDirection;
    float nDotL = saturate(dot(n, toLight));
    float4 albedo = shaderTexture.Sample(SampleType, pin.uv);
    return saturate(diffuseColor * nDotL) * albedo;
}
