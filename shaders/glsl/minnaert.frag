// Minnaert, per pixel (book §5.7.2, §7.4): renormalised interpolated normal, D (max(0,N.V) max(0,N.L))^k max(0,N.L).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform MinnaertPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    float minnaertPower;   // k = m - 1 (errata E5)
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    // Each dot clamped before the product: pow of a negative base is undefined (errata E10).
    float nDotV = max(dot(n, toEye), 0.0);
    float nDotL = max(dot(n, lightDirection), 0.0);
    fragColor = vec4(diffuseColor * pow(nDotV * nDotL, minnaertPower) * nDotL, 1.0);
}
