// SH diffuse transfer per vertex (book §8.2.4 Eq. 18, Ch. 9.2): L_o = sum_i T_i L_i per channel, 4 bands.
#version 450

layout(location = 0) in vec3 position;
// The vertex's transfer coefficients, 16 per channel in four vec4s (albedo/pi included).
layout(location = 1) in vec4 sh_r0;
layout(location = 2) in vec4 sh_r1;
layout(location = 3) in vec4 sh_r2;
layout(location = 4) in vec4 sh_r3;
layout(location = 5) in vec4 sh_g0;
layout(location = 6) in vec4 sh_g1;
layout(location = 7) in vec4 sh_g2;
layout(location = 8) in vec4 sh_g3;
layout(location = 9) in vec4 sh_b0;
layout(location = 10) in vec4 sh_b1;
layout(location = 11) in vec4 sh_b2;
layout(location = 12) in vec4 sh_b3;

layout(std140, binding = 0) uniform ShVertex {
    mat4 modelViewProjection;
    vec4 lightR[4];   // the light's SH coefficients, rotated on the CPU
    vec4 lightG[4];
    vec4 lightB[4];
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vertexColor = vec3(dot(sh_r0, lightR[0]) + dot(sh_r1, lightR[1]) + dot(sh_r2, lightR[2]) + dot(sh_r3, lightR[3]),
                       dot(sh_g0, lightG[0]) + dot(sh_g1, lightG[1]) + dot(sh_g2, lightG[2]) + dot(sh_g3, lightG[3]),
                       dot(sh_b0, lightB[0]) + dot(sh_b1, lightB[1]) + dot(sh_b2, lightB[2]) + dot(sh_b3, lightB[3]));
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
