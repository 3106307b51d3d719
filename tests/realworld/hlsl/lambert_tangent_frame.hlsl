// Lambert diffuse per pixel (book §5.5, §7.1.2) from a D3D9 bump-mapping-style vertex layout: the normal is rebuilt from the TANGENT and BINORMAL streams, as exporters that ship a tangent frame allow.
float4x4 matWorldViewProjection;
float3   vecLightDir;       // object space, unit, toward the light
float4   vecDiffuse;

struct VS_INPUT
{
    float4 Position : POSITION;
    float3 Tangent  : TANGENT;
    float3 Binormal : BINORMAL;
};

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 Normal   : TEXCOORD0;
};

VS_OUTPUT vs_main(VS_INPUT Input)
{
    VS_OUTPUT Output;
    Output.Position = mul(matWorldViewProjection, Input.Position);
    // T x B is the normal of a right-handed frame (B = N x T).
    Output.Normal = cross(Input.Tangent, Input.Binormal);
    return Output;
}

float4 ps_main(VS_OUTPUT Input) : COLOR0
{
    float3 n = normalize(Input.Normal);
    return float4(vecDiffuse.rgb * saturate(dot(n, vecLightDir)), 1.0);
}
