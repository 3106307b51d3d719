// Warn spotlight, per vertex (book §2.4.3, §6.2.1 Diffuse_Warn): D I/d^2 max(0,Lp.L)^alpha max(0,N.Lp).
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform WarnVertex {
    mat4 modelViewProjection;
    vec3 lightDirection;   // object space, unit, toward the light: the spot shines along its negation
    vec3 lightPosition;    // object space
    vec3 diffuseColor;
    vec3 lightColor;
    float warnExponent;    // alpha: the cone's tightness
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vec3 toLight = lightPosition - position;
    float distanceSquared = dot(toLight, toLight);
    vec3 lightDir = toLight * inversesqrt(distanceSquared);
    // Both dots clamped: pow of a negative base is undefined behind the light's plane (errata E11).
    float cone = pow(max(dot(lightDir, lightDirection), 0.0), warnExponent);
    vertexColor = diffuseColor * lightColor / distanceSquared * cone * max(dot(normal, lightDir), 0.0);
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
