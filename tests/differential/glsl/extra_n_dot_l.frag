// The tinted diffuse original (Lambert, book §5.5) ported with one planted convention error: the cosine applied twice (a radiance-vs-BRDF mix-up).
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
    float nl = clamp(dot(n, LightDir), 0.0, 1.0);
    colour = vec4(Tint * nl * nl, 1.0);   // planted: an extra N.L
}
