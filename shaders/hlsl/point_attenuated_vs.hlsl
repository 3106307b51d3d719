// Point light with generalised attenuation, per vertex (book §2.1, §2.3.2): D I max(0,N.Lp) / (A d^2 + B d + C).
matrix Transform     : register(c0);
float3 LightPosition : register(c6);    // object space (w = 1 when transformed, E12)
float3 DiffuseColor  : register(c7);
float3 LightColor    : register(c9);    // I
float3 Attenuation   : register(c10);   // (A, B, C), the D3D9 form

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
    float Distance = length(VertexToLight);
    float3 LightDirection = normalize(VertexToLight);
    float Falloff = Attenuation.x * Distance * Distance + Attenuation.y * Distance + Attenuation.z;
    OutVertex.Diffuse  = DiffuseColor * LightColor * max(0.0f, dot(InVertex.Normal, LightDirection)) / Falloff;
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
