// SH diffuse transfer per vertex from a data texture (book §8.2.4 Eq. 18; vertex texture fetch past the attribute limit): L_o = sum_i T_i L_i, up to 8 bands.
matrix Transform        : register(c0);
float4 TransferLayout   : register(c4);    // (width, height, float4s per channel, 0)
float4 LightR[16]       : register(c5);    // the light's SH coefficients, rotated on the CPU (64 per channel)
float4 LightG[16]       : register(c21);
float4 LightB[16]       : register(c37);
sampler2D TransferMap   : register(s0);    // one row per vertex: R, G, B coefficients, four per texel

struct VS_INPUT
{
    float4 Position : POSITION;
    float4 sh_index : TEXCOORD1;   // x: this vertex's row of TransferMap
};

struct VS_OUTPUT
{
    float4 Position : POSITION;
    float3 Diffuse  : COLOR0;
};

// The texel's centre, so the lookup reads it alone.
float4 Texel(float column, float row)
{
    return tex2Dlod(TransferMap, float4((column + 0.5f) / TransferLayout.x, (row + 0.5f) / TransferLayout.y, 0, 0));
}

VS_OUTPUT main(const VS_INPUT InVertex)
{
    VS_OUTPUT OutVertex;
    OutVertex.Position = mul(Transform, InVertex.Position);
    float row = InVertex.sh_index.x;
    int count = (int)TransferLayout.z;
    float3 diffuse = 0;
    for (int k = 0; k < count; k++)
    {
        diffuse.r += dot(Texel(k, row), LightR[k]);
        diffuse.g += dot(Texel(count + k, row), LightG[k]);
        diffuse.b += dot(Texel(2 * count + k, row), LightB[k]);
    }
    OutVertex.Diffuse = diffuse;
    return OutVertex;
}
