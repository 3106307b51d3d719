// SH diffuse transfer per vertex from a data texture (book §8.2.4 Eq. 18; past the vertex attribute limit): L_o = sum_i T_i L_i per channel, up to 8 bands.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec4 sh_index;   // x: this vertex's row of the transfer texture

layout(std140, binding = 0) uniform ShTextureVertex {
    mat4 modelViewProjection;
    vec4 transferLayout;   // (width, height, vec4s per channel, 0)
    vec4 lightR[16];       // the light's SH coefficients, rotated on the CPU (64 per channel)
    vec4 lightG[16];
    vec4 lightB[16];
};
// One row per vertex: its R, G and B coefficients, four per texel (albedo/pi included).
layout(binding = 1) uniform sampler2D transferMap;

layout(location = 0) out vec3 vertexColor;

void main()
{
    int row = int(sh_index.x);
    int count = int(transferLayout.z);
    vec3 colour = vec3(0.0);
    for (int k = 0; k < count; ++k) {
        colour.r += dot(texelFetch(transferMap, ivec2(k, row), 0), lightR[k]);
        colour.g += dot(texelFetch(transferMap, ivec2(count + k, row), 0), lightG[k]);
        colour.b += dot(texelFetch(transferMap, ivec2(2 * count + k, row), 0), lightB[k]);
    }
    vertexColor = colour;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
