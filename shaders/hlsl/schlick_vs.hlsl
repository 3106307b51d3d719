// Schlick, per vertex (book §5.8.2, §7.6 Schlick_VS): D max(0,N.L) + S t/(n - (n-1)t), t = max(0,R.V); a rational function instead of pow.
matrix Transform     : register(c0);
float3 LightVector   : register(c4);   // object space, unit, toward the light
float3 EyePosition   : register(c5);   // object space
float3 DiffuseColor  : register(c7);
float4 SpecularColor : register(c8);   // w = n, the specular power

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
    float3 Reflection  = normalize(2.0f * N * dot(N, LightVector) - LightVector);
    float RdotV = max(0.0f, dot(Reflection, VertexToEye));
    float n = SpecularColor.w;
    float SchlickTerm = RdotV / (n - (n - 1.0f) * RdotV);   // not gated by N.L (E7)
    float3 Diffuse  = DiffuseColor * max(0.0f, dot(LightVector, N));
    OutVertex.Diffuse  = Diffuse + SpecularColor.rgb * SchlickTerm;
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
