// Ward isotropic, per vertex (book §5.8.1, §7.5.1 Ward_Isotropic_VS): (D + S exp(-tan^2(g)/s^2)/(4 pi s^2)/sqrt(N.L N.V)) max(0,N.L) (E2, E4).
matrix Transform     : register(c0);
float3 LightVector   : register(c4);   // object space, unit, toward the light
float3 EyePosition   : register(c5);   // object space
float3 DiffuseColor  : register(c7);
float3 SpecularColor : register(c8);
float  Roughness     : register(c9);   // sigma, the RMS slope

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
    float3 HalfVector  = normalize(LightVector + VertexToEye);
    float NdotL = dot(N, LightVector);
    float NdotV = dot(N, VertexToEye);

    // The BRDF lives on the upper hemisphere: elsewhere 1/sqrt(N.L N.V) is NaN (E4).
    float3 Specular = 0.0f;
    if (NdotL > 0.0f && NdotV > 0.0f)
    {
        float NdotH = dot(N, HalfVector);          // > 0 here, since N.L and N.V are
        float NdotH2 = NdotH * NdotH;
        float Tan2Gamma = (1.0f - NdotH2) / NdotH2;   // tan^2(acos(N.H)) without acos or tan (E2)
        float RMS2 = Roughness * Roughness;
        float Lobe = exp(-Tan2Gamma / RMS2) / (12.566370614f * RMS2);   // Ward's 1/(4 pi s^2) (E2)
        Specular = SpecularColor * Lobe / sqrt(NdotL * NdotV);
    }

    OutVertex.Diffuse  = (DiffuseColor + Specular) * max(0.0f, NdotL);
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
