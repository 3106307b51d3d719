// Lambert diffuse, per pixel (book §5.5, §7.1.2), MUTANT: the interpolated normal is used as it arrives, without renormalising it; between vertices it is shorter than 1, so the surface darkens across every curved triangle.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform LambertPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 diffuseColor;
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = objectNormal;   // planted bug: normalize() forgotten
    fragColor = vec4(diffuseColor * max(dot(n, lightDirection), 0.0), 1.0);
}
