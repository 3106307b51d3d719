// A tangent-space normal map lighting a diffuse surface (Lambert with a perturbed normal, book §5.5), written as a GL 4.50 original: the textured corpus's normal-map original.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vTangent;
layout(location = 2) in vec2 vUV;
layout(location = 0) out vec4 colour;

layout(binding = 1) uniform Light {
    vec3 LightDir;
    vec3 Base;
};
layout(binding = 2) uniform sampler2D NormalMap;

void main()
{
    // Gram-Schmidt: the interpolated tangent made orthogonal to the renormalised normal.
    vec3 n = normalize(vNormal);
    vec3 t = normalize(vTangent - n * dot(n, vTangent));
    vec3 b = cross(n, t);
    vec3 m = texture(NormalMap, vUV).xyz * 2.0 - 1.0;
    vec3 bumped = normalize(t * m.x + b * m.y + n * m.z);
    colour = vec4(Base * clamp(dot(bumped, LightDir), 0.0, 1.0), 1.0);
}
