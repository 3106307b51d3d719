// Toon shading: saturate(N.L) looked up in a colour ramp texture (Lambert through a lookup, book §5.5 and Ch. 6's lookup textures), in DX9 style: the textured corpus's toon original.
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
sampler2D ToonRamp;         // u = N.L, one row of bands

struct VertexOut
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
};

VertexOut ToonVS(float4 position : POSITION, float3 normal : NORMAL)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, position);
    output.Normal = normal;
    return output;
}

float4 ToonPS(VertexOut input) : COLOR0
{
    float nl = saturate(dot(normalize(input.Normal), LightDir));
    return float4(tex2D(ToonRamp, float2(nl, 0.5)).rgb, 1.0);
}
