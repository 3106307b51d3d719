// CPCA-compressed SH transfer per vertex (book Ch. 9.2.2 SH_VS, Eq. 9.1; Sloan et al. 2003): I = M.L + sum_j w_j (B_j.L) per channel.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec4 sh_cluster;    // x: the cluster's first register in clusteredPca
layout(location = 2) in vec4 sh_weights0;   // the vertex's PCA weights, four per vec4 (zero past the case's count)
layout(location = 3) in vec4 sh_weights1;
layout(location = 4) in vec4 sh_weights2;
layout(location = 5) in vec4 sh_weights3;
layout(location = 6) in vec4 sh_weights4;
layout(location = 7) in vec4 sh_weights5;

layout(std140, binding = 0) uniform ShCpca {
    mat4 modelViewProjection;
    vec4 pcaLayout;            // x: vec4 registers per colour block (PCA vectors / 4)
    vec4 clusteredPca[251];    // per cluster: (M.L r, g, b, 0), then the B_j.L of R, G and B
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vec4 weights[6] = vec4[6](sh_weights0, sh_weights1, sh_weights2, sh_weights3, sh_weights4, sh_weights5);
    int cluster = int(sh_cluster.x);
    int block = int(pcaLayout.x);
    vec4 r = vec4(0.0), g = vec4(0.0), b = vec4(0.0);
    for (int i = 0; i < 6; i++) {
        int offset = cluster + 1 + i;
        r += weights[i] * clusteredPca[offset];
        g += weights[i] * clusteredPca[offset + block];
        b += weights[i] * clusteredPca[offset + 2 * block];
    }
    vec4 one = vec4(1.0);
    vertexColor = clusteredPca[cluster].rgb + vec3(dot(r, one), dot(g, one), dot(b, one));
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
