// SH diffuse plus a specular cube map, per pixel (book Ch. 9.7, "simple specular highlights"): E(n) + spec(R), R = reflect(-V, N).
float4      Irradiance[9] : register(c0);   // rgb: A_l L_i albedo/pi, as sh_irradiance
float3      EyePosition   : register(c9);   // object space
samplerCUBE SpecularMap   : register(s0);   // the specular view of the light, by object-space direction

struct PS_INPUT
{
    float3 InterPos : TEXCOORD0;
    float3 Normal   : TEXCOORD1;
};

float4 main(const PS_INPUT In) : COLOR0
{
    float3 N = normalize(In.Normal);
    float3 S = float3(N.x, -N.z, N.y);   // the normal in the SH frame (z up), Condon-Shortley signs below
    float3 Diffuse = Irradiance[0].rgb * 0.282094791773878
                   - Irradiance[1].rgb * (0.488602511902920 * S.y)
                   + Irradiance[2].rgb * (0.488602511902920 * S.z)
                   - Irradiance[3].rgb * (0.488602511902920 * S.x)
                   + Irradiance[4].rgb * (1.092548430592079 * S.x * S.y)
                   - Irradiance[5].rgb * (1.092548430592079 * S.y * S.z)
                   + Irradiance[6].rgb * (0.315391565252520 * (3.0 * S.z * S.z - 1.0))
                   - Irradiance[7].rgb * (1.092548430592079 * S.x * S.z)
                   + Irradiance[8].rgb * (0.546274215296040 * (S.x * S.x - S.y * S.y));
    float3 PixelToEye = normalize(EyePosition - In.InterPos);
    float3 Mirror = reflect(-PixelToEye, N);   // the direction the eye sees mirrored in the surface
    return float4(Diffuse + texCUBE(SpecularMap, Mirror).rgb, 1.0f);
}
