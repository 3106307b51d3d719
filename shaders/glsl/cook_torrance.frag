// Cook-Torrance, per pixel (book §5.8.3, §7.7): the vertex shader's arithmetic on the renormalised interpolated normal.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform CookTorrancePixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;     // the overall scale: there is no separate Lambert term, as the book
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

    // Defined only where light and eye are both above the surface; the final division needs it (errata E6).
    vec3 color = vec3(0.0);
    if (nDotL > 0.0 && nDotV > 0.0) {
        vec3 halfVector = normalize(lightDirection + toEye);
        float nDotH = max(dot(n, halfVector), 0.0);
        float vDotH = dot(toEye, halfVector);

        // a = acos(N.H) as atan(sqrt(1 - x^2), x), the same angle: Mesa's acos is off by up to
        // 1.6e-4 rad, its atan by ~3e-6. x clamped to 1 as for acos (errata E9; N.H >= 0 already).
        float cosAngle = min(nDotH, 1.0);
        float angle = atan(sqrt((1.0 - cosAngle) * (1.0 + cosAngle)), cosAngle);
        float distribution = gaussianC * exp(-(angle / slopeM) * (angle / slopeM));
        // G divides by V.H, not the book's N.H (errata E6).
        float geometry = max(min(1.0, min(2.0 * nDotH * nDotV / vDotH, 2.0 * nDotH * nDotL / vDotH)), 0.0);
        // Schlick's Fresnel in V.H; the fifth power by multiplies, as pow() of a base an ulp below 0 is undefined.
        float oneMinusVdotH = 1.0 - vDotH;
        float oneMinusVdotH2 = oneMinusVdotH * oneMinusVdotH;
        float fresnel = fresnelR0 + (1.0 - fresnelR0) * (oneMinusVdotH2 * oneMinusVdotH2 * oneMinusVdotH);

        color = diffuseColor * (fresnel * distribution * geometry / (nDotL * nDotV));
    }
    fragColor = vec4(color, 1.0);
}
