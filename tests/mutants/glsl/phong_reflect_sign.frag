// Phong, per pixel (book §5.6.2), MUTANT: the reflection vector's sign is flipped, so the highlight lands on the wrong side.
#version 450

layout(location = 0) in vec3 objectPosition;
layout(location = 1) in vec3 objectNormal;

layout(std140, binding = 1) uniform PhongPixel {
    vec3 lightDirection;
    vec3 eyePosition;
    vec3 diffuseColor;
    vec3 specularColor;
    float specularPower;
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 toEye = normalize(eyePosition - objectPosition);
    vec3 r = -reflect(-lightDirection, n);   // planted bug
    vec3 diffuse = diffuseColor * max(dot(n, lightDirection), 0.0);
    vec3 specular = specularColor * pow(max(dot(r, toEye), 0.0), specularPower);
    fragColor = vec4(diffuse + specular, 1.0);
}
