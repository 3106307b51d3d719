// Ward isotropic, robust per pixel (book §5.8.1, §7.5.1): tan^2 of the half-angle as |N x H|^2 / (N.H)^2, accurate as sigma -> 0.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform WardPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
    float roughness;       // sigma
};

layout(location = 0) out vec4 fragColor;

const float pi = 3.14159265358979;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    float nDotL = dot(n, lightDirection);
    float nDotV = dot(n, toEye);

    vec3 specular = vec3(0.0);
    if (nDotL > 0.0 && nDotV > 0.0) {   // upper hemisphere only (errata E4)
        vec3 halfVector = normalize(lightDirection + toEye);
        float nDotH = dot(n, halfVector);
        // (1 - (N.H)^2) cancels near the peak: an error of 6e-8 in N.H is 1.2e-7 in tan^2,
        // which sigma = 0.001 divides by 1e-6. The cross product has no such cancellation.
        vec3 nCrossH = cross(n, halfVector);
        float tanGamma2 = dot(nCrossH, nCrossH) / (nDotH * nDotH);
        float sigma2 = roughness * roughness;
        // sqrt of each dot: their product can underflow at grazing angles.
        specular = specularColor * (exp(-tanGamma2 / sigma2) / (4.0 * pi * sigma2) / (sqrt(nDotL) * sqrt(nDotV)));
    }
    fragColor = vec4((diffuseColor + specular) * max(nDotL, 0.0), 1.0);
}
