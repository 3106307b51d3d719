// Spotlight with umbra, penumbra and falloff, per vertex (book §2.4): D I s max(0,N.Lp) / (A d^2 + B d + C), penumbra direction corrected (errata E1).
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform SpotVertex {
    mat4 modelViewProjection;
    vec3 lightDirection;   // object space, unit, toward the light: the spot shines along its negation
    vec3 lightPosition;    // object space
    vec3 diffuseColor;
    vec3 lightColor;
    vec3 attenuation;      // (A, B, C): quadratic, linear, constant
    vec3 spotParams;       // (cos umbra, cos penumbra, falloff F); half-angles from the axis
};

layout(location = 0) out vec3 vertexColor;

// 1 inside the umbra, 0 outside the penumbra, and between them rising from the penumbra's
// edge to the umbra's, as D3D9's fixed function (errata E1: the book's ratio is reversed).
float spotFactor(float cosTheta)
{
    float cosUmbra = spotParams.x;
    float cosPenumbra = spotParams.y;
    if (cosTheta >= cosUmbra) return 1.0;
    if (cosTheta <= cosPenumbra) return 0.0;
    return pow((cosTheta - cosPenumbra) / (cosUmbra - cosPenumbra), spotParams.z);
}

void main()
{
    vec3 toLight = lightPosition - position;
    float d = length(toLight);
    vec3 lightDir = toLight / d;
    float falloff = dot(attenuation, vec3(d * d, d, 1.0));
    float spot = spotFactor(dot(lightDir, lightDirection));
    vertexColor = diffuseColor * lightColor * spot * max(dot(normal, lightDir), 0.0) / falloff;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
