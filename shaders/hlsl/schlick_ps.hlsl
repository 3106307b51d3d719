// Schlick, per pixel (book §5.8.2, §7.6 Schlick_PS): D max(0,N.L) + S t/(n - (n-1)t), t = max(0,R.V), normal renormalised.
float3 LightVector   : register(c4);
float3 EyePosition   : register(c5);
float3 DiffuseColor  : register(c7);
float4 SpecularColor : register(c8);   // w = n, the specular power

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    float3 Reflection = normalize(2.0f * N * dot(N, LightVector) - LightVector);
    float RdotV = max(0.0f, dot(Reflection, PixelToEye));
    float n = SpecularColor.w;
    float SchlickTerm = RdotV / (n - (n - 1.0f) * RdotV);   // not gated by N.L (E7)
    float3 Diffuse = DiffuseColor * max(0.0f, dot(LightVector, N));
    return float4(Diffuse + SpecularColor.rgb * SchlickTerm, 1.0f);
}
