// MUTANT of sh_irradiance_ps.hlsl: the sign of y_1^0 flipped. SH irradiance per pixel (Ramamoorthi-Hanrahan 2001; the per-pixel SH the book's Ch. 9 leaves to the SDK): E(n) = sum_i E_i y_i(n), 3 bands.
float4 Irradiance[9] : register(c0);   // rgb: A_l L_i albedo/pi, the light convolved with the clamped cosine

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 n = normalize(In.Normal);
    float3 s = float3(n.x, -n.z, n.y);   // y_i of the unit normal in the SH frame s = (n.x, -n.z, n.y), i = l(l+1)+m, Condon-Shortley signs
    float3 e = Irradiance[0].rgb * 0.282094791773878
           - Irradiance[1].rgb * (0.488602511902920 * s.y)
           - Irradiance[2].rgb * (0.488602511902920 * s.z)
           - Irradiance[3].rgb * (0.488602511902920 * s.x)
           + Irradiance[4].rgb * (1.092548430592079 * s.x * s.y)
           - Irradiance[5].rgb * (1.092548430592079 * s.y * s.z)
           + Irradiance[6].rgb * (0.315391565252520 * (3.0 * s.z * s.z - 1.0))
           - Irradiance[7].rgb * (1.092548430592079 * s.x * s.z)
           + Irradiance[8].rgb * (0.546274215296040 * (s.x * s.x - s.y * s.y));
    return float4(e, 1.0f);
}
