// Ward isotropic, per pixel, literal roughness (book §5.8.1, §7.5.1 Ward_Isotropic_PS, §7.6): ward_iso_ps.hlsl with sigma a literal 0.25, as the book's Ward_Isotropic_PS: 46 vs 51 slots.
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float3 SpecularColor : register(c8);

static const float Roughness = 0.25f;   // sigma: the case's default; --param roughness does not reach it

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    float3 HalfVector = normalize(LightVector + PixelToEye);
    float NdotL = dot(N, LightVector);
    float NdotV = dot(N, PixelToEye);

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

    return float4((DiffuseColor + Specular) * max(0.0f, NdotL), 1.0f);
}
