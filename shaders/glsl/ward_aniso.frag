// Ward anisotropic, per pixel (book §5.8.1, §7.5.2): the vertex shader's arithmetic with the renormalised normal and the interpolated tangent.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;
layout(location = 2) in vec3 objectTangent;

layout(std140, binding = 1) uniform WardAnisoPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
    vec2 roughness;        // (sigma x, sigma y): along the tangent, along N x tangent
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

    // The BRDF lives on the upper hemisphere: 1/sqrt(N.L N.V) is NaN or infinite elsewhere (errata E4).
    // Frame from the mesh tangent, not the book's cross(N, z), which vanishes where N is along z
    // (errata E3). A tangent along N leaves X undefined: no specular there, as the reference.
    vec3 tangentInPlane = objectTangent - n * dot(n, objectTangent);
    vec3 specular = vec3(0.0);
    if (nDotL > 0.0 && nDotV > 0.0 && dot(tangentInPlane, tangentInPlane) >= 1e-12) {
        vec3 x = normalize(tangentInPlane);
        vec3 y = cross(n, x);
        vec2 h = vec2(dot(halfVector, x), dot(halfVector, y)) / roughness;
        float exponent = -2.0 * dot(h, h) / (1.0 + dot(n, halfVector));
        // Ward's normalisation 1/(4 pi sx sy) (errata E2).
        specular = specularColor * (exp(exponent) / (4.0 * pi * roughness.x * roughness.y) / sqrt(nDotL * nDotV));
    }
    fragColor = vec4((diffuseColor + specular) * max(nDotL, 0.0), 1.0);
}
