// Warn spotlight, robust per pixel (book §1.6, §6.3.1, errata E11): no 0 * inf when the light sits on the surface point (d = 0).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform WarnPixel {
    vec3 lightDirection;   // object space, unit, toward the light: the spot shines along its negation
    vec3 lightPosition;    // object space
    vec3 diffuseColor;
    vec3 lightColor;
    float warnExponent;    // alpha
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toLight = lightPosition - objectPosition;
    float distanceSquared = dot(toLight, toLight);
    // d = 0: direction and 1/d^2 undefined; no light rather than NaN. The dots are divided
    // by d^2 before the light colour multiplies, so a tiny d^2 overflows only when the
    // true value does.
    vec3 color = vec3(0.0);
    if (distanceSquared > 0.0) {
        vec3 lightDir = toLight * inversesqrt(distanceSquared);
        float lit = pow(max(dot(lightDir, lightDirection), 0.0), warnExponent) * max(dot(n, lightDir), 0.0);
        if (lit > 0.0)
            color = diffuseColor * lightColor * (lit / distanceSquared);
    }
    fragColor = vec4(color, 1.0);
}
