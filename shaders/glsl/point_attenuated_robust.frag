// Point light with attenuation, robust per pixel (book §2.1, §2.3.2): no 0/0 when the light sits on the surface point (d = 0).
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform PointPixel {
    vec3 lightPosition;    // object space
    vec3 diffuseColor;
    vec3 lightColor;
    vec3 attenuation;      // (A, B, C): quadratic, linear, constant
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toLight = lightPosition - objectPosition;
    float d = length(toLight);
    // At d = 0 the direction is undefined (0/0) and with C = 0 so is the falloff (1/0):
    // the model has no value there. Take no light rather than NaN, which would spread
    // through any later blending or filtering.
    vec3 color = vec3(0.0);
    float lambert = d > 0.0 ? max(dot(n, toLight / d), 0.0) : 0.0;
    if (lambert > 0.0)
        color = diffuseColor * lightColor * (lambert / dot(attenuation, vec3(d * d, d, 1.0)));
    fragColor = vec4(color, 1.0);
}
