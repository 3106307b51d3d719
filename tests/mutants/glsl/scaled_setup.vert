// Setup vertex shader for per-pixel lighting (book §6.3.1), MUTANT: the drawn position is scaled by 1.02 (a stray world scale) while the lighting still uses the unscaled position and normal; the object is drawn 2% too large.
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
    gl_Position = modelViewProjection * vec4(position * 1.02, 1.0);   // planted bug
}
