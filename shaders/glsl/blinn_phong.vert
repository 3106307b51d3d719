// Blinn-Phong, per vertex (book §5.6.3, §7.2.2): D max(0,N.L) + S max(0,N.H)^n, specular not gated by N.L (errata E7).
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform BlinnPhongVertex {
    mat4 modelViewProjection;
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
    float specularPower;
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vec3 toEye = normalize(eyePosition - position);
    vec3 halfVector = normalize(lightDirection + toEye);
    vec3 diffuse = diffuseColor * max(dot(normal, lightDirection), 0.0);
    vec3 specular = specularColor * pow(max(dot(normal, halfVector), 0.0), specularPower);
    vertexColor = diffuse + specular;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
