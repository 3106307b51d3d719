// Lambert diffuse per pixel (book §5.5, §7.1.2), as a D3D9 effect or D3D11 tutorial writes it: row vectors, mul(v, M) with the D3DX (row-vector) matrix, both stages in one file.
float4x4 WorldViewProj;     // D3DX convention: clip = v * WorldViewProj
float3   LightDir;          // object space, unit, toward the light
float3   MaterialDiffuse;

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

VertexOut LightVertexShader(VertexIn input)
{
    VertexOut output;
    output.Position = mul(input.Position, WorldViewProj);
    output.Normal = input.Normal;
    return output;
}

float4 LightPixelShader(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Normal);
    float diffuse = saturate(dot(n, LightDir));
    return float4(MaterialDiffuse * diffuse, 1.0);
}
