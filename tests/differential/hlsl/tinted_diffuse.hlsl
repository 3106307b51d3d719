// A tinted diffuse term, saturate(N.L) times a material colour (Lambert, book §5.5), written by a D3D9 author as the "original" of the differential corpus: the case names no model, its ports are judged against this render.
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
float3   Tint;

struct VertexIn
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct VertexOut
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
};

VertexOut TintVS(VertexIn input)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, input.Position);
    output.Normal = input.Normal;
    return output;
}

float4 TintPS(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Normal);
    return float4(Tint * saturate(dot(n, LightDir)), 1.0);
}
