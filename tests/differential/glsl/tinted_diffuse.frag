// The tinted diffuse original ported to GLSL 4.50 by hand (Lambert, book §5.5): the correct port.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 0) out vec4 colour;

layout(binding = 1) uniform Material {
    vec3 LightDir;
    vec3 Tint;
};

void main()
{
    vec3 n = normalize(vNormal);
    colour = vec4(Tint * clamp(dot(n, LightDir), 0.0, 1.0), 1.0);
}
