// The tinted diffuse original (Lambert, book §5.5) ported with one planted convention error: the interpolated normal used without renormalising it.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 0) out vec4 colour;

layout(binding = 1) uniform Material {
    vec3 LightDir;
    vec3 Tint;
};

void main()
{
    vec3 n = vNormal;   // planted: no normalize()
    colour = vec4(Tint * clamp(dot(n, LightDir), 0.0, 1.0), 1.0);
}
