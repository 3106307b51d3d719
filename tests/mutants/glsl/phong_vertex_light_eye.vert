// Phong per pixel (book §5.6.2, §7.2.1), MUTANT (vertex-stage vectors): L and V are normalised here, per vertex, and the fragment stage uses them as interpolated, as two public per-pixel effects do.
#version 450

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

layout(std140, binding = 0) uniform PhongSetup {
    mat4 modelViewProjection;
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
};

layout(location = 0) out vec3 objectNormal;   // not unit length once interpolated
layout(location = 1) out vec3 toLight;        // unit here; shorter than 1 between vertices where it varies
layout(location = 2) out vec3 toEye;          // unit here, shorter than 1 between vertices

void main()
{
    objectNormal = normal;
    // planted bug: unit per vertex, then interpolated; the fragment stage does not renormalise
    toLight = normalize(lightDirection);
    toEye = normalize(eyePosition - position);
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
