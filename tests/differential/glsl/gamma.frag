// The tinted diffuse original (Lambert, book §5.5) ported with one planted convention error: a gamma 2.2 encoding of the output the original leaves linear.
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
    vec3 c = Tint * clamp(dot(n, LightDir), 0.0, 1.0);
    colour = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);   // planted: gamma-encodes its output
}
