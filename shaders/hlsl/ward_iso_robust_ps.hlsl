// Ward isotropic, robust per pixel (book §5.8.1, §7.5.1): tan^2 of the half-angle as |N x H|^2 / (N.H)^2, accurate as sigma -> 0.
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float3 SpecularColor : register(c8);
float  Roughness     : register(c9);   // sigma

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 V = normalize(EyePosition - In.InterPos);
    float NdotL = dot(N, LightVector);
    float NdotV = dot(N, V);

    float3 Specular = 0.0f;
    if (NdotL > 0.0f && NdotV > 0.0f)   // upper hemisphere only (E4)
    {
        float3 H = normalize(LightVector + V);
        float NdotH = dot(N, H);
        float3 NxH = cross(N, H);                        // no cancellation near the peak, unlike 1 - (N.H)^2
        float Tan2Gamma = dot(NxH, NxH) / (NdotH * NdotH);
        float RMS2 = Roughness * Roughness;
        float Lobe = exp(-Tan2Gamma / RMS2) / (12.566370614f * RMS2);   // 1/(4 pi s^2) (E2)
        Specular = SpecularColor * Lobe / (sqrt(NdotL) * sqrt(NdotV));   // no underflow of the product
    }
    return float4((DiffuseColor + Specular) * max(0.0f, NdotL), 1.0f);
}
