// SH diffuse transfer per vertex (book §8.2.4 Eq. 18, Ch. 9.2): L_o = sum_i T_i L_i per channel, 4 bands.
matrix Transform : register(c0);
float4 LightR[4] : register(c4);    // the light's SH coefficients, rotated on the CPU
float4 LightG[4] : register(c8);
float4 LightB[4] : register(c12);

struct VS_INPUT
{
    float4 Position : POSITION;
    // The vertex's transfer coefficients, 16 per channel (albedo/pi included).
    float4 sh_r0 : TEXCOORD1;
    float4 sh_r1 : TEXCOORD2;
    float4 sh_r2 : TEXCOORD3;
    float4 sh_r3 : TEXCOORD4;
    float4 sh_g0 : TEXCOORD5;
    float4 sh_g1 : TEXCOORD6;
    float4 sh_g2 : TEXCOORD7;
    float4 sh_g3 : TEXCOORD8;
    float4 sh_b0 : TEXCOORD9;
    float4 sh_b1 : TEXCOORD10;
    float4 sh_b2 : TEXCOORD11;
    float4 sh_b3 : TEXCOORD12;
};

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 Diffuse  : COLOR0;
};

VS_OUTPUT main(const VS_INPUT InVertex)
{
    VS_OUTPUT OutVertex;
    OutVertex.Position = mul(Transform, InVertex.Position);
    OutVertex.Diffuse  = float3(dot(InVertex.sh_r0, LightR[0]) + dot(InVertex.sh_r1, LightR[1]) + dot(InVertex.sh_r2, LightR[2]) + dot(InVertex.sh_r3, LightR[3]),
                                dot(InVertex.sh_g0, LightG[0]) + dot(InVertex.sh_g1, LightG[1]) + dot(InVertex.sh_g2, LightG[2]) + dot(InVertex.sh_g3, LightG[3]),
                                dot(InVertex.sh_b0, LightB[0]) + dot(InVertex.sh_b1, LightB[1]) + dot(InVertex.sh_b2, LightB[2]) + dot(InVertex.sh_b3, LightB[3]));
    return OutVertex;
}
