// Lambert diffuse per pixel (book §5.5, §7.1.2) with the normal packed in the vertex colour, n = 2 c - 1, as meshes for fixed-function-era hardware stored it; the inputs named as the author's mesh loader calls them.
#version 450

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec4 aPackedNormal;   // rgb = 0.5 + 0.5 n

layout(std140, binding = 0) uniform Camera {
    mat4 uMVP;
};

layout(location = 0) out vec3 vPacked;

void main()
{
    vPacked = aPackedNormal.rgb;
    gl_Position = uMVP * vec4(aPos, 1.0);
}
