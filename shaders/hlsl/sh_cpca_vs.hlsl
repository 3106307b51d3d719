// CPCA-compressed SH transfer per vertex (book Ch. 9.2.2 SH_VS, Eq. 9.1; Sloan et al. 2003): I = M.L + sum_j w_j (B_j.L) per channel.
matrix Transform          : register(c0);
float4 PcaLayout          : register(c4);   // x: float4 registers per colour block (PCA vectors / 4)
float4 ClusteredPCA[251]  : register(c5);   // per cluster: (M.L r, g, b, 0), then the B_j.L of R, G and B

struct VS_INPUT
{
    float4 Position    : POSITION;
    float4 sh_cluster  : TEXCOORD1;   // x: the cluster's first register in ClusteredPCA
    float4 sh_weights0 : TEXCOORD2;   // the vertex's PCA weights, four per float4 (zero past the case's count)
    float4 sh_weights1 : TEXCOORD3;
    float4 sh_weights2 : TEXCOORD4;
    float4 sh_weights3 : TEXCOORD5;
    float4 sh_weights4 : TEXCOORD6;
    float4 sh_weights5 : TEXCOORD7;
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
    float4 weights[6] = { InVertex.sh_weights0, InVertex.sh_weights1, InVertex.sh_weights2,
                          InVertex.sh_weights3, InVertex.sh_weights4, InVertex.sh_weights5 };
    int cluster = (int)InVertex.sh_cluster.x;
    int block = (int)PcaLayout.x;
    float4 R = 0, G = 0, B = 0;
    for (int i = 0; i < 6; i++)
    {
        int offset = cluster + 1 + i;
        R += weights[i] * ClusteredPCA[offset];
        G += weights[i] * ClusteredPCA[offset + block];
        B += weights[i] * ClusteredPCA[offset + 2 * block];
    }
    float3 diffuse = ClusteredPCA[cluster].rgb;   // the cluster mean's term of Eq. 9.1
    diffuse.r += dot(R, 1);
    diffuse.g += dot(G, 1);
    diffuse.b += dot(B, 1);
    OutVertex.Diffuse = diffuse;
    return OutVertex;
}
