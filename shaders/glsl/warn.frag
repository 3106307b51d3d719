// Warn spotlight, per pixel (book §2.4.3, §6.3.1 Diffuse_Warn_PS20): cone, distance and Lambert per pixel, both dots clamped (errata E11).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform WarnPixel {
    vec3 lightDirection;   // object space, unit, toward the light: the spot shines along its negation
    vec3 lightPosition;    // object space
    vec3 diffuseColor;
    vec3 lightColor;
    float warnExponent;    // alpha: the cone's tightness
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toLight = lightPosition - objectPosition;
    float distanceSquared = dot(toLight, toLight);
    vec3 lightDir = toLight * inversesqrt(distanceSquared);
    // The book's PS leaves the Lambert dot unclamped; both are clamped here (errata E11).
    float cone = pow(max(dot(lightDir, lightDirection), 0.0), warnExponent);
    fragColor = vec4(diffuseColor * lightColor / distanceSquared * cone * max(dot(n, lightDir), 0.0), 1.0);
}
