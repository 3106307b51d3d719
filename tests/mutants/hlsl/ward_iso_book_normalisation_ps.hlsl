// Ward isotropic, per pixel (book §5.8.1, §7.5.1 Ward_Isotropic_PS), MUTANT: the lobe is normalised by the book's printed 1/(2 pi sigma^2) instead of Ward's 1/(4 pi sigma^2) (errata E2), so the specular term is twice as strong.
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float3 SpecularColor : register(c8);
float  Roughness     : register(c9);   // sigma, the RMS slope

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

    float3 Specular = 0.0f;
    if (NdotL > 0.0f && NdotV > 0.0f)
    {
        float NdotH = dot(N, HalfVector);
        float NdotH2 = NdotH * NdotH;
        float Tan2Gamma = (1.0f - NdotH2) / NdotH2;
        float RMS2 = Roughness * Roughness;
        float Lobe = exp(-Tan2Gamma / RMS2) / (6.283185307f * RMS2);   // planted bug: the book's 2 pi
        Specular = SpecularColor * Lobe / sqrt(NdotL * NdotV);
    }

    return float4((DiffuseColor + Specular) * max(0.0f, NdotL), 1.0f);
}
