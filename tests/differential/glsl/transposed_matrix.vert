// The tinted diffuse original's vertex stage (Lambert, book §5.5) ported with a planted convention error: HLSL's mul(M, v) written as v * M, i.e. the matrix transposed (the row/column convention).
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 vNormal;

layout(binding = 0) uniform Transforms {
    mat4 WorldViewProj;
};

void main()
{
    gl_Position = position * WorldViewProj;   // planted: row-vector order with a column-vector matrix
    vNormal = normal;
}
