// Ward isotropic, per pixel (book §5.8.1, §7.5.1), MUTANT: the lobe is normalised by the book's printed 1/(2 pi sigma^2) instead of Ward's 1/(4 pi sigma^2) (errata E2), so the specular term is twice as strong.
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
    vec3 halfVector = normalize(lightDirection + toEye);
    float nDotL = dot(n, lightDirection);
    float nDotV = dot(n, toEye);

    vec3 specular = vec3(0.0);
    if (nDotL > 0.0 && nDotV > 0.0) {
        float nDotH = dot(n, halfVector);
        float nDotH2 = nDotH * nDotH;
        float tanGamma2 = (1.0 - nDotH2) / nDotH2;
        float sigma2 = roughness * roughness;
        specular = specularColor * (exp(-tanGamma2 / sigma2) / (2.0 * pi * sigma2) / sqrt(nDotL * nDotV));   // planted bug: 2 pi
    }
    fragColor = vec4((diffuseColor + specular) * max(nDotL, 0.0), 1.0);
}
