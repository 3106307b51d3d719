// Lambert with a tangent-space normal map and an ambient term (book §5.5, §2.5), GLSL 4.50: the original.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vTangent;
layout(location = 2) in vec2 vUV;
layout(location = 0) out vec4 colour;

layout(binding = 1) uniform Light {
    vec3 LightDir;          // object space, unit, toward the light
    vec3 Base;
    vec3 AmbientLight;
};
layout(binding = 2) uniform sampler2D NormalMap;

void main()
{
    vec3 N = normalize(vNormal);
    vec3 T = normalize(vTangent - N * dot(N, vTangent));
    vec3 B = cross(N, T);
    vec3 tangentNormal = texture(NormalMap, vUV).xyz * 2.0 - 1.0;
    vec3 perturbed = normalize(T * tangentNormal.x + B * tangentNormal.y + N * tangentNormal.z);
    float lambert = max(dot(perturbed, LightDir), 0.0);
    colour = vec4(Base * (AmbientLight + vec3(lambert)), 1.0);
}
