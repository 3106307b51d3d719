// Point light with DirectX-style attenuation, per pixel (book §2.1, §2.3.2): distance and direction per pixel, D I max(0,N.Lp) / (A d^2 + B d + C).
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
    vec3 lightDir = toLight / d;
    float falloff = dot(attenuation, vec3(d * d, d, 1.0));
    fragColor = vec4(diffuseColor * lightColor * max(dot(n, lightDir), 0.0) / falloff, 1.0);
}
