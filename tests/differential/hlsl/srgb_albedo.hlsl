// An sRGB-stored albedo texture (the sampler decodes it to linear) times saturate(N.L) plus an ambient term (Lambert with a texture, book §5.5 and §2.5), in DX9 style: the textured corpus's sRGB original.
float4x4 WorldViewProj;
float3   LightDir;          // object space, unit, toward the light
float3   Ambient;
sampler2D Albedo;           // SRGBTexture: texels decoded to linear before filtering

struct VertexOut
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
    float2 UV       : TEXCOORD1;
};

VertexOut AlbedoVS(float4 position : POSITION, float3 normal : NORMAL, float2 uv : TEXCOORD0)
{
    VertexOut output;
    output.Position = mul(WorldViewProj, position);
    output.Normal = normal;
    output.UV = uv;
    return output;
}

float4 AlbedoPS(VertexOut input) : COLOR0
{
    float3 albedo = tex2D(Albedo, input.UV).rgb;
    return float4(albedo * (saturate(dot(normalize(input.Normal), LightDir)) + Ambient), 1.0);
}
