// Warn spotlight, per pixel with the power LUT (book §2.4.3, §6.3.3): the cone's dot^alpha looked up instead of pow().
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform WarnPixel {
    vec3 lightDirection;   // object space, unit, toward the light: the spot shines along its negation
    vec3 lightPosition;    // object space
    vec3 diffuseColor;
    vec3 lightColor;
    float warnExponent;    // alpha: selects the LUT row
    float powerLutRows;    // rows in the LUT; row j holds exponent j
};

// R32F, column i the base u = (i + 0.5)/width, row j the exponent j, value u^j; linear, clamp to edge.
layout(binding = 2) uniform sampler2D powerLut;

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toLight = lightPosition - objectPosition;
    float distanceSquared = dot(toLight, toLight);
    vec3 lightDir = toLight * inversesqrt(distanceSquared);
    // v at the centre of row alpha, so only u is filtered (errata E11: the dot is clamped at 0).
    vec2 lookup = vec2(max(dot(lightDir, lightDirection), 0.0), (warnExponent + 0.5) / powerLutRows);
    float cone = texture(powerLut, lookup).r;
    fragColor = vec4(diffuseColor * lightColor / distanceSquared * cone * max(dot(n, lightDir), 0.0), 1.0);
}
