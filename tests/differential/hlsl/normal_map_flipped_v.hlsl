// The GL normal-map original (Lambert with a perturbed normal, book §5.5) ported to DX9 HLSL with one planted texture error: v flipped (D3D top-down rows taken for GL bottom-up ones).
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
float3   Base;
sampler2D NormalMap;

struct VertexOut
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
    float3 Tangent  : TEXCOORD1;
    float2 UV       : TEXCOORD2;
};

VertexOut BumpVS(float4 position : POSITION, float3 normal : NORMAL, float3 tangent : TANGENT, float2 uv : TEXCOORD0)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, position);
    output.Normal = normal;
    output.Tangent = tangent;
    output.UV = uv;
    return output;
}

float4 BumpPS(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Normal);
    float3 t = normalize(input.Tangent - n * dot(n, input.Tangent));
    float3 b = cross(n, t);
    float3 m = tex2D(NormalMap, float2(input.UV.x, 1.0 - input.UV.y)).xyz * 2.0 - 1.0;
    float3 bumped = normalize(t * m.x + b * m.y + n * m.z);
    return float4(Base * saturate(dot(bumped, LightDir)), 1.0);
}
