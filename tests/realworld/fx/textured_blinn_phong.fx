// Blinn-Phong per pixel, directional light (book §5.6.3, §7.2.2), written as a DirectX 9 SDK-style effect whose application sets the texture variable and leaves the tweakables at their initial values.

float4x4 g_mWorld : WORLD;
float4x4 g_mWorldViewProjection : WORLDVIEWPROJECTION;
float3 g_vLightDir : DIRECTION = { 0.0f, 1.0f, 0.0f };   // world space, toward the light
float3 g_vEyePos : CAMERAPOSITION;                        // world space

// Tweakables: the application never sets these, so D3DX uploads their initial values.
float3 g_vDiffuseTint < string UIWidget = "Color"; > = { 0.5, 0.5, 0.5 };
float3 g_vSpecular < string UIWidget = "Color"; > = float3( 0.3f, 0.3f, 0.3f );
float g_fShininess < float UIMin = 1; float UIMax = 128; > = 12.0f;

// The application calls effect->SetTexture("g_tAlbedo", ...): the texture, not the sampler.
texture g_tAlbedo < string ResourceName = "albedo.dds"; >;

sampler2D AlbedoSampler = sampler_state
{
    Texture = <g_tAlbedo>;
    MinFilter = LINEAR;
    MagFilter = LINEAR;
    MipFilter = LINEAR;
    AddressU = WRAP;
    AddressV = WRAP;
};

struct VS_OUT
{
    float4 Pos      : POSITION;
    float3 Normal   : TEXCOORD0;
    float3 WorldPos : TEXCOORD1;
    float2 UV       : TEXCOORD2;
};

VS_OUT TexturedVS( float4 Pos : POSITION, float3 Normal : NORMAL, float2 UV : TEXCOORD0 )
{
    VS_OUT Out;
    Out.Pos = mul( Pos, g_mWorldViewProjection );
    Out.Normal = mul( Normal, (float3x3)g_mWorld );
    Out.WorldPos = mul( Pos, g_mWorld ).xyz;
    Out.UV = UV;
    return Out;
}

float4 TexturedPS( VS_OUT In ) : COLOR0
{
    float3 N = normalize( In.Normal );
    float3 L = normalize( g_vLightDir );
    float3 H = normalize( L + normalize( g_vEyePos - In.WorldPos ) );
    float3 albedo = tex2D( AlbedoSampler, In.UV ).rgb * g_vDiffuseTint;
    float3 color = albedo * saturate( dot( N, L ) ) + g_vSpecular * pow( saturate( dot( N, H ) ), g_fShininess );
    return float4( color, 1.0f );
}

technique Textured
{
    pass P0
    {
        VertexShader = compile vs_2_0 TexturedVS();
        PixelShader  = compile ps_2_0 TexturedPS();
        CullMode = CCW;
        ZEnable = TRUE;
    }
}
