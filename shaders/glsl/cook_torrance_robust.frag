// Cook-Torrance, robust per pixel (book §5.8.3, §7.7): the facet angle from atan(|N x H|, N.H), accurate as m -> 0.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform CookTorrancePixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;     // the overall scale
    float gaussianC;       // Blinn's constant c
    float slopeM;          // m, the RMS facet slope (radians)
    float fresnelR0;       // reflectance at normal incidence
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    float nDotL = dot(n, lightDirection);
    float nDotV = dot(n, toEye);

    vec3 color = vec3(0.0);
    if (nDotL > 0.0 && nDotV > 0.0) {   // errata E6: defined on the upper hemisphere only
        vec3 halfVector = normalize(lightDirection + toEye);
        float nDotH = max(dot(n, halfVector), 0.0);
        float vDotH = dot(toEye, halfVector);
        // The angle from its sine and cosine: sqrt(1 - (N.H)^2) cancels near the peak (an
        // error of 6e-8 in N.H is one of 3e-4 rad in the angle), |N x H| does not. With
        // m = 0.001 the lobe lives within a few 1e-3 rad of H.
        float angle = atan(length(cross(n, halfVector)), nDotH);
        float slope = angle / slopeM;
        float distribution = gaussianC * exp(-slope * slope);
        float geometry = clamp(2.0 * nDotH * min(nDotV, nDotL) / vDotH, 0.0, 1.0);   // G over V.H (E6)
        float f = 1.0 - vDotH;
        float f2 = f * f;
        float fresnel = fresnelR0 + (1.0 - fresnelR0) * (f2 * f2 * f);   // Schlick in V.H (E6)
        // Divided one dot at a time: the product of two small dots can underflow to 0.
        color = diffuseColor * (fresnel * distribution * geometry / nDotL / nDotV);
    }
    fragColor = vec4(color, 1.0);
}
