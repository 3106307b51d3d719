// A glossy finish: saturate(N.L) diffuse plus a Blinn-Phong highlight gated by N.L (book §5.6.3), bright enough to pass 1.0; the differential corpus's second original.
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
float3   EyePosition;       // object space
float3   Base;
float3   Gloss;
float    Sharpness;

struct VertexOut
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
    float3 ToEye    : TEXCOORD1;
};

VertexOut GlossyVS(float4 position : POSITION, float3 normal : NORMAL)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, position);
    output.Normal = normal;
    output.ToEye = EyePosition - position.xyz;
    return output;
}

float4 GlossyPS(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Normal);
    float3 v = normalize(input.ToEye);
    float3 h = normalize(LightDir + v);
    float nl = dot(n, LightDir);
    float highlight = nl > 0 ? pow(saturate(dot(n, h)), Sharpness) : 0;
    return float4(Base * saturate(nl) + Gloss * highlight, 1.0);
}
