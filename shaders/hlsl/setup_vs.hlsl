// Setup vertex shader for per-pixel lighting (book §6.3.1, Basic_PS20_Setup): object-space position and normal to the pixel shader.
matrix Transform : register(c0);   // World * View * Projection

struct VS_INPUT
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
};

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 InterPos : TEXCOORD0;   // object-space position
    float3 Normal   : TEXCOORD1;   // object-space normal; not unit length once interpolated
};

VS_OUTPUT main(const VS_INPUT InVertex)
{
    VS_OUTPUT OutVertex;
    OutVertex.Position = mul(Transform, InVertex.Position);
    OutVertex.InterPos = InVertex.Position.xyz;
    OutVertex.Normal   = InVertex.Normal;
    return OutVertex;
}
