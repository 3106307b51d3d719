// Lambert diffuse per pixel (book §5.5), MUTANT (derivative normal): N is rebuilt from screen-space derivatives of the position, normalize(cross(dFdx(P), dFdy(P))), a flat facet normal, instead of the interpolated vertex normal.
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
    // planted bug: one normal per triangle (and its sign follows the API's window y)
    vec3 n = normalize(cross(dFdx(objectPosition), dFdy(objectPosition)));
    fragColor = vec4(diffuseColor * max(dot(n, lightDirection), 0.0), 1.0);
}
