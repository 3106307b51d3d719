// Ward anisotropic, per pixel (book §5.8.1, §7.5.2 Ward_Anisotropic_PS): the VS's lobe with the interpolated frame re-orthonormalised (E2, E3, E4).
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float3 SpecularColor : register(c8);
float2 Roughness     : register(c9);   // (sigma_x, sigma_y) along X and Y

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
    float3 Tangent  : TEXCOORD2;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    float3 HalfVector = normalize(LightVector + PixelToEye);
    float NdotL = dot(N, LightVector);
    float NdotV = dot(N, PixelToEye);

    // X: the interpolated tangent orthogonalised against the renormalised N (E3); its length does not matter.
    float3 TangentInPlane = In.Tangent - N * dot(N, In.Tangent);

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

    return float4((DiffuseColor + Specular) * max(0.0f, NdotL), 1.0f);
}
