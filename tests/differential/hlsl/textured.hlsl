// A texture-modulated diffuse term, tex2D(DiffuseMap, uv) times saturate(N.L) (Lambert with a texture, book §5.5 and Ch. 6's lookups), in DX9 style: the differential corpus's textured original.
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
sampler2D DiffuseMap;

struct VertexOut
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
    float2 UV       : TEXCOORD1;
};

VertexOut TexturedVS(float4 position : POSITION, float3 normal : NORMAL, float2 uv : TEXCOORD0)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, position);
    output.Normal = normal;
    output.UV = uv;
    return output;
}

float4 TexturedPS(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Normal);
    return float4(tex2D(DiffuseMap, input.UV).rgb * saturate(dot(n, LightDir)), 1.0);
}
