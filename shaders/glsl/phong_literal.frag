// Phong, per pixel, literal power (book §5.6.2, §7.2.1 Phong_PS, §7.6): phong.frag with the power a literal 7, as the book's Phong_PS: 21 vs 37 slots.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform PhongPixel {
    vec3 lightDirection;   // object space, unit, toward the light
    vec3 eyePosition;      // object space
    vec3 diffuseColor;
    vec3 specularColor;
};

layout(location = 0) out vec4 fragColor;

const float specularPower = 7.0;   // the case's default power; --param power does not reach it

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 r = reflect(-lightDirection, n);
    vec3 diffuse = diffuseColor * max(dot(n, lightDirection), 0.0);
    vec3 specular = specularColor * pow(max(dot(r, toEye), 0.0), specularPower);
    fragColor = vec4(diffuse + specular, 1.0);
}
