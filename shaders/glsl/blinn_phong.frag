// Blinn-Phong, per pixel (book §5.6.3, §7.2.2): renormalised interpolated normal, D max(0,N.L) + S max(0,N.H)^n.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform BlinnPhongPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
    float specularPower;
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 halfVector = normalize(lightDirection + toEye);
    vec3 diffuse = diffuseColor * max(dot(n, lightDirection), 0.0);
    // Not gated by N.L, as the book's shaders (errata E7).
    vec3 specular = specularColor * pow(max(dot(n, halfVector), 0.0), specularPower);
    fragColor = vec4(diffuse + specular, 1.0);
}
