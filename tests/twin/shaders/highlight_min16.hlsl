// Blinn-Phong highlight per pixel (book §5.6.3), ported to min16float for a mobile GPU: desktop drivers compute it in 32 bits, a 16-bit device does not.
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
    min16float3 n = normalize((min16float3)input.Normal);
    min16float3 h = normalize((min16float3)LightDir + normalize((min16float3)input.ToEye));
    min16float highlight = pow(saturate(dot(n, h)), (min16float)Sharpness);
    return float4(Base * saturate(dot(n, (min16float3)LightDir)) + highlight, 1.0);
}
