// Blinn-Phong, per pixel (book §5.6.3, §7.2.2 Blinn_Phong_PS): D max(0,N.L) + S max(0,N.H)^n with the interpolated normal renormalised.
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float4 SpecularColor : register(c8);   // w = specular power

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
    float3 Diffuse  = DiffuseColor * max(0.0f, dot(LightVector, N));
    float3 Specular = SpecularColor.rgb * pow(max(0.0f, dot(N, HalfVector)), SpecularColor.w);
    return float4(Diffuse + Specular, 1.0f);
}
