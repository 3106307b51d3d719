// Lambert diffuse, per pixel (book §5.5), MUTANT (window-origin convention): the normal is rebuilt from screen-space derivatives, N = normalize(cross(dFdx(P), dFdy(P))), an order that is right only where window y grows downwards (Vulkan, D3D). On GL window y grows upwards, dFdy changes sign and N points into the surface. Only a flat-faced shape (the cube) can match the reference at all.
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
    // planted bug: the facet normal's sign depends on the API's window y direction
    vec3 n = normalize(cross(dFdx(objectPosition), dFdy(objectPosition)));
    fragColor = vec4(diffuseColor * max(dot(n, lightDirection), 0.0), 1.0);
}
