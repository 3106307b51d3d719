// Lambert diffuse per pixel (book §5.5, §7.1.2), written as a D3D9 tutorial writes it: both stages in one file, entry points named for what they do, the author's own uniform names.
float4x4 WorldViewProj;
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
    output.Position = mul(WorldViewProj, input.Position);
    output.Normal = input.Normal;
    return output;
}

float4 LightPixelShader(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Normal);
    float diffuse = saturate(dot(n, LightDir));
    return float4(MaterialDiffuse * diffuse, 1.0);
}
