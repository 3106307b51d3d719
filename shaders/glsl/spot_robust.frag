// Spotlight, robust per pixel (book §2.4, errata E1): no 0/0 when the light sits on the surface point (d = 0).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform SpotPixel {
    vec3 lightDirection;   // object space, unit, toward the light: the spot shines along its negation
    vec3 lightPosition;    // object space
    vec3 diffuseColor;
    vec3 lightColor;
    vec3 attenuation;      // (A, B, C): quadratic, linear, constant
    vec3 spotParams;       // (cos umbra, cos penumbra, falloff F)
};

layout(location = 0) out vec4 fragColor;

// 1 inside the umbra, 0 outside the penumbra, rising toward the umbra between (E1).
float spotFactor(float cosTheta)
{
    if (cosTheta >= spotParams.x) return 1.0;
    if (cosTheta <= spotParams.y) return 0.0;
    return pow((cosTheta - spotParams.y) / (spotParams.x - spotParams.y), spotParams.z);
}

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toLight = lightPosition - objectPosition;
    float d = length(toLight);
    // d = 0: direction, cone angle and falloff are undefined; no light rather than NaN.
    vec3 color = vec3(0.0);
    if (d > 0.0) {
        vec3 lightDir = toLight / d;
        float lit = spotFactor(dot(lightDir, lightDirection)) * max(dot(n, lightDir), 0.0);
        if (lit > 0.0)
            color = diffuseColor * lightColor * (lit / dot(attenuation, vec3(d * d, d, 1.0)));
    }
    fragColor = vec4(color, 1.0);
}
