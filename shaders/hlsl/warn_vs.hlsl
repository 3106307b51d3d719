// Warn spotlight, per vertex (book §1.6, Ch.6 Diffuse_Warn): D I/d^2 max(0,Lp.L)^a max(0,N.Lp), both dots clamped (E11).
matrix Transform     : register(c0);
float3 LightVector   : register(c4);    // the negated spot axis: unit, from the surface toward the light
float3 LightPosition : register(c6);    // object space
float3 DiffuseColor  : register(c7);
float3 LightColor    : register(c9);    // I
float  WarnExponent  : register(c10);   // a

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
    float3 VertexToLight = LightPosition - InVertex.Position.xyz;
    float3 LightDirection = normalize(VertexToLight);
    float3 Intensity = LightColor / dot(VertexToLight, VertexToLight);   // inverse square
    // Clamped before pow: a negative base is NaN (E11).
    float Warn = pow(max(0.0f, dot(LightDirection, LightVector)), WarnExponent);
    OutVertex.Diffuse  = DiffuseColor * Intensity * Warn * max(0.0f, dot(InVertex.Normal, LightDirection));
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
