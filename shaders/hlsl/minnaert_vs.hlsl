// Minnaert, per vertex (book §5.7.2, §7.4 Minnaert_VS): D (max(0,N.V) max(0,N.L))^k max(0,N.L), k = m - 1 (E5, E10).
matrix Transform     : register(c0);
float3 LightVector   : register(c4);   // object space, unit, toward the light
float3 EyePosition   : register(c5);   // object space
float3 DiffuseColor  : register(c7);
float  MinnaertPower : register(c9);   // k = m - 1: the shader multiplies by the irradiance

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
    float3 N = InVertex.Normal;
    float3 VertexToEye = normalize(EyePosition - InVertex.Position.xyz);
    // Each dot clamped before the product: pow of a negative product is NaN (E10).
    float VdotN = max(0.0f, dot(VertexToEye, N));
    float Irradiance = max(0.0f, dot(LightVector, N));
    OutVertex.Diffuse  = DiffuseColor * pow(VdotN * Irradiance, MinnaertPower) * Irradiance;
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
