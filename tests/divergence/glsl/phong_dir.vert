// Phong from a directional light with diffuse, specular and ambient colours (book §5.5, §5.6.2, §5.6.4), GLSL 4.50: the original's vertex stage.
#version 450
layout(location = 0) in vec4 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 vNormal;
layout(location = 1) out vec3 vView;

layout(binding = 0) uniform Camera {
    mat4 ModelViewProjection;
    vec3 CameraPosition;
};

void main()
{
    gl_Position = ModelViewProjection * position;
    vNormal = normal;
    vView = CameraPosition - position.xyz;
}
