// Blinn-Phong, per vertex (book §5.6.3, §7.2.2 Blinn_Phong_VS), MUTANT: the half vector L + V is not renormalised. Its length is 2 cos(angle(L, V)/2), up to 2 where the eye and the light agree, so N.H exceeds 1 and the highlight is raised to the n-th power of it.
matrix Transform     : register(c0);
float3 LightVector   : register(c4);   // object space, unit, toward the light
float3 EyePosition   : register(c5);   // object space
float3 DiffuseColor  : register(c7);
float4 SpecularColor : register(c8);   // w = specular power, as the book packs it

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
    float3 HalfVector  = LightVector + VertexToEye;   // planted bug: normalize() forgotten
    float3 Diffuse  = DiffuseColor * max(0.0f, dot(LightVector, N));
    float3 Specular = SpecularColor.rgb * pow(max(0.0f, dot(N, HalfVector)), SpecularColor.w);
    OutVertex.Diffuse  = Diffuse + Specular;
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
