// Lambert diffuse, per vertex (book §5.5, §7.1.2): D * max(0, N.L) in object space.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform LambertVertex {
    mat4 modelViewProjection;
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 diffuseColor;
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vertexColor = diffuseColor * max(dot(normal, lightDirection), 0.0);
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
