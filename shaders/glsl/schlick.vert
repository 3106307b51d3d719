// Schlick, per vertex (book §5.8.2, §7.6): D max(0,N.L) + S t/(n - (n-1)t), t = max(0,R.V): Phong's look without pow.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform SchlickVertex {
    mat4 modelViewProjection;
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
    float specularPower;   // Schlick's n
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vec3 toEye = normalize(eyePosition - position);
    vec3 r = reflect(-lightDirection, normal);
    float t = max(dot(r, toEye), 0.0);
    vec3 diffuse = diffuseColor * max(dot(normal, lightDirection), 0.0);
    // Denominator >= 1 for n >= 1 and t in [0, 1]; not gated by N.L (errata E7).
    vec3 specular = specularColor * (t / (specularPower - (specularPower - 1.0) * t));
    vertexColor = diffuse + specular;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
