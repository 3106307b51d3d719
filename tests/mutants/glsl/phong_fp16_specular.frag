// Phong, per pixel (book §5.6.2, §7.2.1), MUTANT (precision): R.V is rounded to half precision before the power, as a mediump/half temporary would be on a GPU that honours it; the relative error 2^-11 of R.V grows n-fold in (R.V)^n, up to ~1.7e-3 in the highlight.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform PhongPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
    float specularPower;
};

layout(location = 0) out vec4 fragColor;

// Round to the nearest fp16 value (desktop GLSL keeps mediump at 32 bits, so the rounding is spelled out).
float toHalf(float x)
{
    return unpackHalf2x16(packHalf2x16(vec2(x, 0.0))).x;
}

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 r = reflect(-lightDirection, n);
    vec3 diffuse = diffuseColor * max(dot(n, lightDirection), 0.0);
    float rDotV = toHalf(max(dot(r, toEye), 0.0));   // planted bug: a half-precision temporary
    vec3 specular = specularColor * pow(rDotV, specularPower);
    fragColor = vec4(diffuse + specular, 1.0);
}
