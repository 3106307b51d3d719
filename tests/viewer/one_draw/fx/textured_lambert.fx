// Lambert (book §3, the diffuse term) as a DX9 effect with a texture, its own vertex semantics and pass states.
float4x4 WorldViewProj;
float3 LightDir;        // object space, towards the light
float3 DiffuseColour;

texture AlbedoMap;
sampler AlbedoSampler = sampler_state
{
    Texture = <AlbedoMap>;
    MinFilter = Linear;
    MagFilter = Linear;
    AddressU = Wrap;
    AddressV = Wrap;
};

// Normals and texture coordinates come in on slots no default mapping would choose.
struct AppToVertex
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD5;
    float2 Uv       : TEXCOORD2;
};

struct VertexToPixel
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
    float2 Uv       : TEXCOORD1;
};

VertexToPixel TexturedLambertVS(AppToVertex input)
{
    VertexToPixel output;
    output.Position = mul(input.Position, WorldViewProj);
    output.Normal = input.Normal;
    output.Uv = input.Uv;
    return output;
}

float4 TexturedLambertPS(VertexToPixel input) : COLOR0
{
    float3 albedo = tex2D(AlbedoSampler, input.Uv).rgb;
    float diffuse = max(dot(normalize(input.Normal), LightDir), 0.0);
    return float4(DiffuseColour * albedo * diffuse, 1.0);
}

technique TexturedLambert
{
    pass P0
    {
        // Back faces culled and no depth test: without the pass's states the far side of
        // the shape would be drawn over the near side.
        CullMode = CCW;
        ZEnable = false;
        VertexShader = compile vs_2_0 TexturedLambertVS();
        PixelShader = compile ps_2_0 TexturedLambertPS();
    }
}
