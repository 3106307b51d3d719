// Spotlight, per vertex (book §2.4): umbra, penumbra and falloff over an attenuated point light, penumbra ramp as D3D9 (E1).
matrix Transform     : register(c0);
float3 LightVector   : register(c4);    // the negated spot axis: unit, from the surface toward the light
float3 LightPosition : register(c6);    // object space
float3 DiffuseColor  : register(c7);
float3 LightColor    : register(c9);    // I
float3 Attenuation   : register(c10);   // (A, B, C)
float3 SpotParams    : register(c11);   // (cos umbra, cos penumbra, falloff): half-angles as cosines

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

    // 1 inside the umbra, 0 outside the penumbra, a ramp rising toward the umbra between (E1).
    float CosTheta = dot(LightDirection, LightVector);
    float Spot;
    if (CosTheta >= SpotParams.x)
        Spot = 1.0f;
    else if (CosTheta <= SpotParams.y)
        Spot = 0.0f;
    else
        Spot = pow((CosTheta - SpotParams.y) / (SpotParams.x - SpotParams.y), SpotParams.z);

    OutVertex.Diffuse  = DiffuseColor * LightColor * Spot * max(0.0f, dot(InVertex.Normal, LightDirection)) / Falloff;
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
