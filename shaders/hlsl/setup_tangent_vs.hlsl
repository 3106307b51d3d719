// Setup vertex shader with a tangent (book §6.3.1 Basic_PS20_Setup plus §7.5.2's advice to pass tangents): position, normal and tangent to the pixel shader.
matrix Transform : register(c0);   // World * View * Projection

struct VS_INPUT
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
    float3 Tangent  : TANGENT;
};

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 InterPos : TEXCOORD0;   // object-space position
    float3 Normal   : TEXCOORD1;   // object-space normal; not unit length once interpolated
    float3 Tangent  : TEXCOORD2;   // object-space tangent; re-orthogonalised in the pixel shader
};

VS_OUTPUT main(const VS_INPUT InVertex)
{
    VS_OUTPUT OutVertex;
    OutVertex.Position = mul(Transform, InVertex.Position);
    OutVertex.InterPos = InVertex.Position.xyz;
    OutVertex.Normal   = InVertex.Normal;
    OutVertex.Tangent  = InVertex.Tangent;
    return OutVertex;
}
