// Blinn-Phong highlight per pixel (book §5.6.3) in full float: the original the min16float port is judged against.
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
float3   EyePosition;       // object space
float3   Base;
float    Sharpness;

struct VertexOut
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
    float3 ToEye    : TEXCOORD1;
};

VertexOut HighlightVS(float4 position : POSITION, float3 normal : NORMAL)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, position);
    output.Normal = normal;
    output.ToEye = EyePosition - position.xyz;
    return output;
}

float4 HighlightPS(VertexOut input) : COLOR0
{
    float3 n = normalize(input.Normal);
    float3 h = normalize(LightDir + normalize(input.ToEye));
    float highlight = pow(saturate(dot(n, h)), Sharpness);
    return float4(Base * saturate(dot(n, LightDir)) + highlight, 1.0);
}
