// Lambert per pixel, directional light (book §5.5, §7.1.2), written as an effect shared between a D3D10 and a D3D9 build: the D3D10 state objects and technique10 sit under an #if the D3D9 build turns off.

#define FX_TARGET_D3D10 0

float4x4 matWorld : World;
float4x4 matWorldViewProj : WorldViewProjection;
float3 vLightDirection : Direction;   // world space, toward the light
float4 vMaterialDiffuse : Diffuse;

struct VertexOutput
{
    float4 position : POSITION;
    float3 normal   : TEXCOORD0;
};

VertexOutput LambertVS( float4 position : POSITION, float3 normal : NORMAL )
{
    VertexOutput output;
    output.position = mul( position, matWorldViewProj );
    output.normal = mul( normal, (float3x3)matWorld );
    return output;
}

float4 LambertPS( VertexOutput input ) : COLOR0
{
    float NdotL = saturate( dot( normalize( input.normal ), normalize( vLightDirection ) ) );
    return float4( vMaterialDiffuse.rgb * NdotL, 1.0f );
}

#if FX_TARGET_D3D10
RasterizerState BackFaceCulling
{
    CullMode = Back;
    FillMode = Solid;
};

DepthStencilState DepthOn
{
    DepthEnable = TRUE;
    DepthWriteMask = ALL;
};

technique10 Lambert
{
    pass P0
    {
        SetVertexShader( CompileShader( vs_4_0, LambertVS() ) );
        SetGeometryShader( NULL );
        SetPixelShader( CompileShader( ps_4_0, LambertPS() ) );
        SetRasterizerState( BackFaceCulling );
        SetDepthStencilState( DepthOn, 0 );
    }
}
#else
technique Lambert
{
    pass P0
    {
        VertexShader = compile vs_3_0 LambertVS();
        PixelShader  = compile ps_3_0 LambertPS();
        CullMode = CCW;
        ZEnable = TRUE;
    }
}
#endif
