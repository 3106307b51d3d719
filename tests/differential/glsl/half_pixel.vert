// The tinted diffuse original's vertex stage (Lambert, book §5.5) ported with a planted convention error: D3D9's half-pixel offset applied to clip space, for a 64x64 target (the corpus test's size).
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 vNormal;

layout(binding = 0) uniform Transforms {
    mat4 WorldViewProj;
};

void main()
{
    gl_Position = WorldViewProj * position;
    gl_Position.xy += vec2(-1.0, 1.0) / 64.0 * gl_Position.w;   // planted: half a pixel left and up
    vNormal = normal;
}
