// Oren-Nayar, per vertex (book §5.7.1, §7.3 Oren-Nayar_VS): D max(0,N.L) (A + B cosC sin(alpha) tan(beta)) (E8, E9).
matrix Transform        : register(c0);
float3 LightVector      : register(c4);   // object space, unit, toward the light
float3 EyePosition      : register(c5);   // object space
float3 DiffuseColor     : register(c7);
float  RoughnessSquared : register(c9);   // sigma^2: A and B depend only on it

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
    float3 N = normalize(InVertex.Normal);   // a normal past unit length breaks sin(alpha) near pi (hard cases)
    float3 VertexToEye = normalize(EyePosition - InVertex.Position.xyz);
    float VdotN = dot(VertexToEye, N);
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
        float3 ViewProjected  = VertexToEye - N * VdotN;
        float3 LightProjected = LightVector - N * LdotN;
        float CosC = 0.0f;
        if (dot(ViewProjected, ViewProjected) >= 1e-12f && dot(LightProjected, LightProjected) >= 1e-12f)
            CosC = max(0.0f, dot(normalize(ViewProjected), normalize(LightProjected)));

        float A = 1.0f - 0.5f * RoughnessSquared / (RoughnessSquared + 0.33f);
        float B = 0.45f * RoughnessSquared / (RoughnessSquared + 0.09f);
        Color = DiffuseColor * LdotN * (A + B * CosC * SinAlpha * TanBeta);
    }

    OutVertex.Diffuse  = Color;
    OutVertex.Position = mul(Transform, InVertex.Position);
    return OutVertex;
}
