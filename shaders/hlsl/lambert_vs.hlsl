// Lambert diffuse, per vertex (book §5.5, §7.1.2 Diffuse_VS): D * max(0, N.L) with an object-space light vector.
matrix Transform    : register(c0);
float3 LightVector  : register(c4);   // object space, unit, toward the light
float3 DiffuseColor : register(c7);

struct VS_INPUT
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 Diffuse  : COLOR0;
};

VS_OUTPUT main(const VS_INPUT InVertex)
{
    VS_OUTPUT OutVertex;
    OutVertex.Position = mul(Transform, InVertex.Position);
    OutVertex.Diffuse  = DiffuseColor * max(0.0f, dot(LightVector, InVertex.Normal));
    return OutVertex;
}
