// Schlick, per pixel (book §5.8.2, §7.6): renormalised interpolated normal, D max(0,N.L) + S t/(n - (n-1)t), t = max(0,R.V).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform SchlickPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
    float specularPower;   // Schlick's n
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 r = reflect(-lightDirection, n);
    float t = max(dot(r, toEye), 0.0);
    vec3 diffuse = diffuseColor * max(dot(n, lightDirection), 0.0);
    // Not gated by N.L, as the book's shaders (errata E7).
    vec3 specular = specularColor * (t / (specularPower - (specularPower - 1.0) * t));
    fragColor = vec4(diffuse + specular, 1.0);
}
