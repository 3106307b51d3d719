// Lambert diffuse per pixel (book §5.5, §7.1.2), written for Vulkan: the material in a second descriptor set.
#version 450

layout(location = 0) in vec3 inNormal;

layout(set = 1, binding = 0) uniform MaterialUBO {
    vec4 lightDirection;   // toward the light, unit
    vec4 diffuse;
} material;

layout(location = 0) out vec4 outColor;

void main()
{
    vec3 N = normalize(inNormal);
    outColor = vec4(material.diffuse.rgb * max(dot(N, material.lightDirection.xyz), 0.0), 1.0);
}
