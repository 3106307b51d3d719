// Ambient term (book §2.5, Appendix C ambient.hsl): one constant colour for every vertex.
matrix Transform    : register(c0);
float3 AmbientColor : register(c7);

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 Diffuse  : COLOR0;
};

VS_OUTPUT main(float4 Position : POSITION)
{
    VS_OUTPUT OutVertex;
    OutVertex.Position = mul(Transform, Position);
    OutVertex.Diffuse  = AmbientColor;
    return OutVertex;
}
