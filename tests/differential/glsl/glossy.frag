// The glossy original (Blinn-Phong, book §5.6.3) ported to GLSL 4.50: the correct port.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vToEye;
layout(location = 0) out vec4 colour;

layout(binding = 1) uniform Finish {
    vec3 LightDir;
    vec3 Base;
    vec3 Gloss;
    float Sharpness;
};

void main()
{
    vec3 n = normalize(vNormal);
    vec3 v = normalize(vToEye);
    vec3 h = normalize(LightDir + v);
    float nl = dot(n, LightDir);
    float highlight = nl > 0.0 ? pow(clamp(dot(n, h), 0.0, 1.0), Sharpness) : 0.0;
    colour = vec4(Base * clamp(nl, 0.0, 1.0) + Gloss * highlight, 1.0);
}
