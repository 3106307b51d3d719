// Point light with DirectX-style attenuation, per vertex (book §2.1, §2.3.2): D I max(0,N.Lp) / (A d^2 + B d + C).
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform PointVertex {
    mat4 modelViewProjection;
    vec3 lightPosition;    // object space
    vec3 diffuseColor;
    vec3 lightColor;
    vec3 attenuation;      // (A, B, C): quadratic, linear, constant
};

layout(location = 0) out vec3 vertexColor;

void main()
{
    vec3 toLight = lightPosition - position;
    float d = length(toLight);
    vec3 lightDir = toLight / d;
    float falloff = dot(attenuation, vec3(d * d, d, 1.0));
    vertexColor = diffuseColor * lightColor * max(dot(normal, lightDir), 0.0) / falloff;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
