// Blinn-Phong per pixel (book §5.6.3, §7.2.2), the "~/port" DX9 effect of the README's init example: globals with semantics, one technique.
float4x4 WorldViewProj : WORLDVIEWPROJECTION;   // row vectors, as D3DX builds them
float3 LightDir : DIRECTION = { 0.0f, 1.0f, 0.0f };   // object space, toward the light
float3 EyePosition : CAMERAPOSITION;                   // object space
float3 DiffuseColor : DIFFUSE = { 1.0f, 1.0f, 1.0f };
float3 SpecularColor : SPECULAR = { 1.0f, 1.0f, 1.0f };
float SpecularPower : SPECULARPOWER = 7.0f;

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
    float3 View     : TEXCOORD1;
};

VS_OUTPUT BlinnVS(float4 pos : POSITION, float3 normal : NORMAL)
{
    VS_OUTPUT o;
    o.Position = mul(pos, WorldViewProj);
    o.Normal = normal;
    o.View = EyePosition - pos.xyz;
    return o;
}

float4 BlinnPS(VS_OUTPUT i) : COLOR0
{
    float3 n = normalize(i.Normal);
    float3 h = normalize(LightDir + normalize(i.View));
    float diffuse = saturate(dot(n, LightDir));
    float specular = pow(saturate(dot(n, h)), SpecularPower);
    return float4(DiffuseColor * diffuse + SpecularColor * specular, 1.0f);
}

technique BlinnPhong
{
    pass P0
    {
        VertexShader = compile vs_2_0 BlinnVS();
        PixelShader = compile ps_2_0 BlinnPS();
    }
}
