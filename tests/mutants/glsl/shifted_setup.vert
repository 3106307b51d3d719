// Setup vertex shader for per-pixel lighting (book §6.3.1), MUTANT: a leftover model offset of 1.5 units along +Y is added to the drawn position but not to the lit one; the object is drawn about 1.5 pixels too high at 96x96 (4 at 256x256) with its shading left behind.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform Transforms {
    mat4 modelViewProjection;
};

layout(location = 0) out vec3 objectPosition;
layout(location = 1) out vec3 objectNormal;

void main()
{
    objectPosition = position;
    objectNormal = normal;
    gl_Position = modelViewProjection * vec4(position + vec3(0.0, 1.5, 0.0), 1.0);   // planted bug
}
