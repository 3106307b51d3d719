// Oren-Nayar, per pixel, arithmetic (book §5.7.1, §7.3): D max(0,N.L) (A + B cosC sin(alpha) tan(beta)) (E8, E9), normal renormalised.
float3 LightVector      : register(c4);
float3 EyePosition      : register(c5);
float3 DiffuseColor     : register(c7);
float  RoughnessSquared : register(c9);   // sigma^2

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    float VdotN = dot(PixelToEye, N);
    float LdotN = dot(LightVector, N);

    // max(0, N.L) = 0 zeroes the colour; testing it first also keeps tan(beta) finite below.
    float3 Color = 0.0f;
    if (LdotN > 0.0f)
    {
        // sin(alpha) tan(beta) straight from the dots: acos falls, so alpha = acos(min dot) and
        // beta = acos(max dot); sin(acos c) = sqrt(1 - c^2) and tan(acos c) = sqrt(1 - c^2)/c.
        // The same function as the angles, without the driver's acos (off by up to 1.6e-4 rad
        // on Mesa) and tan's blow-up near 90 degrees. The clamp is E9's.
        float CosAlpha = clamp(min(VdotN, LdotN), -1.0f, 1.0f);
        float CosBeta  = clamp(max(VdotN, LdotN), -1.0f, 1.0f);   // >= N.L > 0
        float SinAlpha = sqrt((1.0f - CosAlpha) * (1.0f + CosAlpha));
        float TanBeta  = sqrt((1.0f - CosBeta) * (1.0f + CosBeta)) / CosBeta;

        // cos C from the tangent-plane projections; 0 where a projection vanishes (E8).
        float3 ViewProjected  = PixelToEye - N * VdotN;
        float3 LightProjected = LightVector - N * LdotN;
        float CosC = 0.0f;
        if (dot(ViewProjected, ViewProjected) >= 1e-12f && dot(LightProjected, LightProjected) >= 1e-12f)
            CosC = max(0.0f, dot(normalize(ViewProjected), normalize(LightProjected)));

        float A = 1.0f - 0.5f * RoughnessSquared / (RoughnessSquared + 0.33f);
        float B = 0.45f * RoughnessSquared / (RoughnessSquared + 0.09f);
        Color = DiffuseColor * LdotN * (A + B * CosC * SinAlpha * TanBeta);
    }

    return float4(Color, 1.0f);
}
