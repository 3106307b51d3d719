// Ward anisotropic, per vertex (book §5.8.1, §7.5.2 Ward_Anisotropic_VS): elliptical lobe in the mesh tangent frame (E2, E3, E4).
matrix Transform     : register(c0);
float3 LightVector   : register(c4);   // object space, unit, toward the light
float3 EyePosition   : register(c5);   // object space
float3 DiffuseColor  : register(c7);
float3 SpecularColor : register(c8);
float2 Roughness     : register(c9);   // (sigma_x, sigma_y) along X and Y

struct VS_INPUT
{
    float4 Position : POSITION;
    float3 Normal   : NORMAL;
    float3 Tangent  : TANGENT;
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
    float3 HalfVector  = normalize(LightVector + VertexToEye);
    float NdotL = dot(N, LightVector);
    float NdotV = dot(N, VertexToEye);

    // X: the mesh tangent orthogonalised against N, not the book's cross(N, z), NaN where N is along z (E3).
    float3 TangentInPlane = InVertex.Tangent - N * dot(N, InVertex.Tangent);

    // The BRDF lives on the upper hemisphere: elsewhere 1/sqrt(N.L N.V) is NaN (E4).
    // A tangent along N leaves X undefined: no specular there, as the reference does.
    float3 Specular = 0.0f;
    if (NdotL > 0.0f && NdotV > 0.0f && dot(TangentInPlane, TangentInPlane) >= 1e-12f)
    {
        float3 X = normalize(TangentInPlane);
        float3 Y = cross(N, X);
        float HdotX = dot(HalfVector, X) / Roughness.x;
        float HdotY = dot(HalfVector, Y) / Roughness.y;
        float Exponent = -2.0f * (HdotX * HdotX + HdotY * HdotY) / (1.0f + dot(N, HalfVector));
        float Normalisation = 1.0f / (12.566370614f * Roughness.x * Roughness.y);   // Ward's 1/(4 pi sx sy) (E2)
        Specular = SpecularColor * Normalisation / sqrt(NdotL * NdotV) * exp(Exponent);
    }

    OutVertex.Diffuse  = (DiffuseColor + Specular) * max(0.0f, NdotL);
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
