// Ward isotropic, per pixel, literal roughness (book §5.8.1, §7.5.1 Ward_Isotropic_PS, §7.6): ward_iso.frag with sigma a literal 0.25, as the book's Ward_Isotropic_PS: 46 vs 51 slots.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform WardPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
};

layout(location = 0) out vec4 fragColor;

const float pi = 3.14159265358979;
const float roughness = 0.25;   // sigma: the case's default; --param roughness does not reach it

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 halfVector = normalize(lightDirection + toEye);
    float nDotL = dot(n, lightDirection);
    float nDotV = dot(n, toEye);

    // The BRDF lives on the upper hemisphere: 1/sqrt(N.L N.V) is NaN or infinite elsewhere (errata E4).
    vec3 specular = vec3(0.0);
    if (nDotL > 0.0 && nDotV > 0.0) {
        float nDotH = dot(n, halfVector);
        float nDotH2 = nDotH * nDotH;
        float tanGamma2 = (1.0 - nDotH2) / nDotH2;   // tan^2(acos(N.H)) without trig (errata E2)
        float sigma2 = roughness * roughness;
        // Ward's normalisation 1/(4 pi sigma^2), not the book's 2 pi (errata E2).
        specular = specularColor * (exp(-tanGamma2 / sigma2) / (4.0 * pi * sigma2) / sqrt(nDotL * nDotV));
    }
    fragColor = vec4((diffuseColor + specular) * max(nDotL, 0.0), 1.0);
}
