// Ward isotropic, per pixel with the volume LUT (book §5.8.1, §7.5.1 Ward_Isotropic_PS_Tex): the specular factor looked up by (N.L, N.V, N.H).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform WardPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
};

// R32F volume over (N.L, N.V, N.H) in [0, 1]^3, no scale or bias, holding
// exp(-tan^2(g)/s^2) / (4 pi s^2) / sqrt(N.L N.V) for the case's fixed sigma; trilinear, clamp to edge.
layout(binding = 2) uniform sampler3D wardLut;

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 halfVector = normalize(lightDirection + toEye);
    float nDotL = dot(n, lightDirection);
    float nDotV = dot(n, toEye);
    float nDotH = dot(n, halfVector);

    // Same upper-hemisphere gate as the arithmetic shader (errata E4): clamp to edge would
    // otherwise turn N.V <= 0 into the edge texel's large value.
    vec3 specular = vec3(0.0);
    if (nDotL > 0.0 && nDotV > 0.0)
        specular = specularColor * texture(wardLut, vec3(nDotL, nDotV, nDotH)).r;
    fragColor = vec4((diffuseColor + specular) * max(nDotL, 0.0), 1.0);
}
