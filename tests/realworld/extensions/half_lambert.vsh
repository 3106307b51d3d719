// Lambert or half-Lambert diffuse per pixel (book §5.5, §7.1.2), vertex stage in a .vsh file as Apple's and Cocos samples name them.
#version 330 core
in vec3 position;
in vec3 normal;

uniform mat4 modelViewProjectionMatrix;

out vec3 fragNormal;

void main()
{
    fragNormal = normal;
    gl_Position = modelViewProjectionMatrix * vec4(position, 1.0);
}
