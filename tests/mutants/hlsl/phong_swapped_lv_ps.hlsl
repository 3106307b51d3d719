// Phong, per pixel (book §5.6.2, §7.2.1 Phong_PS), MUTANT: L and V are swapped. R.V is symmetric in L and V, so the highlight survives; the diffuse term becomes N.V, lighting the side that faces the eye.
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
    // planted bug: the pixel-to-eye vector is used as L and the light vector as V
    float3 L = normalize(EyePosition - In.InterPos);
    float3 V = LightVector;
    float3 Reflection = normalize(2.0f * N * dot(N, L) - L);
    float3 Diffuse  = DiffuseColor * max(0.0f, dot(L, N));
    float3 Specular = SpecularColor.rgb * pow(max(dot(Reflection, V), 0.0f), SpecularColor.w);
    return float4(Diffuse + Specular, 1.0f);
}
