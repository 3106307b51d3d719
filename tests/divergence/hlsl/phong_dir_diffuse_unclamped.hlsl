// Phong from a directional light with diffuse, specular and ambient colours (book §5.5, §5.6.2, §5.6.4), ported to HLSL SM5 with row-vector matrices; planted bug (diffuse_unclamped): max(N.L, 0) missing on the diffuse term: negative light on the dark side.
cbuffer Transforms
{
    float4x4 worldViewProj;     // row-vector convention: mul(v, M)
    float3   eyePos;
};

cbuffer Surface
{
    float3 toLight;
    float3 kd;
    float3 ks;
    float3 ka;
    float  power;
};

struct VertexInput
{
    float4 pos : POSITION;
    float3 nrm : NORMAL;
};

struct PixelInput
{
    float4 pos : SV_Position;
    float3 nrm : TEXCOORD0;
    float3 eye : TEXCOORD1;
};

PixelInput PhongVS(VertexInput input)
{
    PixelInput output;
    output.pos = mul(input.pos, worldViewProj);
    output.nrm = input.nrm;
    output.eye = eyePos - input.pos.xyz;
    return output;
}

float4 PhongPS(PixelInput input) : SV_Target
{
    float3 n = normalize(input.nrm);
    float3 e = normalize(input.eye);
    float lambert = dot(n, toLight);
    float3 r = 2.0 * lambert * n - toLight;
    float phong = lambert > 0.0 ? pow(saturate(dot(r, e)), power) : 0.0;
    float3 diffuse = kd * lambert;
    return float4(ka + diffuse + ks * phong, 1.0);
}
