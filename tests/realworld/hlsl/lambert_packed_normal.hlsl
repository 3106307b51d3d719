// Lambert diffuse per pixel (book §5.5, §7.1.2) with the normal packed in the vertex colour (COLOR0, n = 2 c - 1), both stages in one D3D9-style file.
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
float3   MaterialDiffuse;

struct VertexIn
{
    float4 Position : POSITION;
    float4 Packed   : COLOR0;   // rgb = 0.5 + 0.5 n
};

struct VertexOut
{
    float4 Position : POSITION;
    float3 Packed   : TEXCOORD0;
};

VertexOut PackedNormalVS(VertexIn input)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, input.Position);
    output.Packed = input.Packed.rgb;
    return output;
}

float4 PackedNormalPS(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Packed * 2.0 - 1.0);
    return float4(MaterialDiffuse * saturate(dot(n, LightDir)), 1.0);
}
