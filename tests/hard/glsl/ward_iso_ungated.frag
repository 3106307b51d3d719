// Ward isotropic without the hemisphere gate (book §5.8.1 as printed; errata E4): deliberately broken, for tests/hard.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform WardPixel {
    vec3 lightDirection;
    vec3 eyePosition;
    vec3 diffuseColor;
    vec3 specularColor;
    float roughness;
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 h = normalize(lightDirection + toEye);
    float nDotL = dot(n, lightDirection);
    float nDotV = dot(n, toEye);
    float nDotH = dot(n, h);
    float tan2 = (1.0 - nDotH * nDotH) / (nDotH * nDotH);
    float s2 = roughness * roughness;
    vec3 specular = specularColor * exp(-tan2 / s2) / (4.0 * 3.14159265 * s2) / sqrt(nDotL * nDotV);
    fragColor = vec4((diffuseColor + specular) * max(nDotL, 0.0), 1.0);
}
