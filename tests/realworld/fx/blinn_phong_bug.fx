// Blinn-Phong per pixel, directional light (book §5.6.3, §7.2.2), DirectX 9 SDK sample style, with a planted bug: the view vector points from the eye to the surface, so H is built from the wrong vector.

//--------------------------------------------------------------------------------------
// Global variables (an effect-aware application fills them by semantic)
//--------------------------------------------------------------------------------------
float4x4 g_mWorld : WORLD;                              // row vectors, as D3DX builds them
float4x4 g_mWorldViewProjection : WORLDVIEWPROJECTION;

float3 g_LightDir : DIRECTION
<
    string UIName = "Light direction";
    string Space = "World";
> = { 0.0f, 1.0f, 0.0f };                              // world space, toward the light

float3 g_EyePosition : CAMERAPOSITION;                  // world space

float3 g_MaterialDiffuse : DIFFUSE < string UIWidget = "Color"; > = { 1.0f, 1.0f, 1.0f };
float3 g_MaterialSpecular : SPECULAR < string UIWidget = "Color"; > = { 1.0f, 1.0f, 1.0f };
float g_fSpecularPower : SPECULARPOWER
<
    string UIWidget = "Slider";
    float UIMin = 1.0f;
    float UIMax = 128.0f;
> = 7.0f;

string g_Description = "Per-pixel Blinn-Phong";

texture g_MeshTexture < string ResourceName = "detail.dds"; >;

sampler MeshTextureSampler = sampler_state
{
    Texture = <g_MeshTexture>;
    MinFilter = LINEAR;
    MagFilter = LINEAR;
    MipFilter = LINEAR;
    AddressU = WRAP;
    AddressV = WRAP;
};

//--------------------------------------------------------------------------------------
// Vertex shader output structure
//--------------------------------------------------------------------------------------
struct VS_OUTPUT
{
    float4 Position : POSITION;   // vertex position
    float3 Normal   : TEXCOORD0;  // world-space normal
    float3 WorldPos : TEXCOORD1;  // world-space position
    float2 TexUV    : TEXCOORD2;  // detail texture coordinate
};

//--------------------------------------------------------------------------------------
// Transforms to clip space and passes world-space normal and position on
//--------------------------------------------------------------------------------------
VS_OUTPUT RenderSceneVS( float4 vPos : POSITION,
                         float3 vNormal : NORMAL,
                         float2 vTexCoord0 : TEXCOORD0 )
{
    VS_OUTPUT Output;
    Output.Position = mul( vPos, g_mWorldViewProjection );
    Output.Normal = mul( vNormal, (float3x3)g_mWorld );   // world is a rotation: no inverse-transpose needed
    Output.WorldPos = mul( vPos, g_mWorld ).xyz;
    Output.TexUV = vTexCoord0;
    return Output;
}

//--------------------------------------------------------------------------------------
// Blinn-Phong: diffuse N.L plus specular (N.H)^n, H halfway between L and V
//--------------------------------------------------------------------------------------
float4 RenderScenePS( VS_OUTPUT In, uniform bool bSpecular ) : COLOR0
{
    float3 N = normalize( In.Normal );
    float3 L = normalize( g_LightDir );
    float3 V = normalize( In.WorldPos - g_EyePosition );
    float3 H = normalize( L + V );

    float3 color = g_MaterialDiffuse * saturate( dot( N, L ) );
    if( bSpecular )
        color += g_MaterialSpecular * pow( saturate( dot( N, H ) ), g_fSpecularPower );
    return float4( color, 1.0f );
}

//--------------------------------------------------------------------------------------
// Techniques
//--------------------------------------------------------------------------------------
technique RenderSceneBlinnPhong
<
    string Description = "Diffuse and specular";
>
{
    pass P0
    {
        VertexShader = compile vs_2_0 RenderSceneVS();
        PixelShader  = compile ps_2_0 RenderScenePS( true );

        CullMode = CCW;
        ZEnable = TRUE;
        ZWriteEnable = TRUE;
        AlphaBlendEnable = FALSE;
        Lighting = FALSE;
    }
}

technique RenderSceneDiffuseOnly
{
    pass P0
    {
        VertexShader = compile vs_2_0 RenderSceneVS();
        PixelShader  = compile ps_2_0 RenderScenePS( false );
        CullMode = CCW;
        ZEnable = TRUE;
    }
}
