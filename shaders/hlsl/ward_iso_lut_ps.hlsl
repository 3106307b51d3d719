// Ward isotropic, per pixel with the 3D LUT (book §7.5.1 Ward_Isotropic_PS_Tex, Fill_WardIsotropic_Texture): the lobe read at (N.L, N.V, N.H) (E2, E4).
float3    LightVector   : register(c4);
float3    EyePosition   : register(c5);
float3    DiffuseColor  : register(c7);
float3    SpecularColor : register(c8);
sampler3D WardTex       : register(s1);   // R32F exp(-tan^2 g/s^2)/(4 pi s^2)/sqrt(x y) over (0, 1)^3, no scale/bias;
                                          // sampler3D, not the book's plain sampler: glslang types that as 2D even under tex3D

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
    float3 DotProducts = float3(dot(LightVector, N), dot(PixelToEye, N), dot(HalfVector, N));   // (N.L, N.V, N.H)

    // Same upper-hemisphere gate as the arithmetic shader (E4): the clamped lookup
    // would otherwise return the grazing-angle edge texels below the horizon.
    float3 Specular = 0.0f;
    if (DotProducts.x > 0.0f && DotProducts.y > 0.0f)
        Specular = SpecularColor * tex3D(WardTex, DotProducts).x;

    return float4((DiffuseColor + Specular) * max(0.0f, DotProducts.x), 1.0f);
}
