// Phong per pixel (book §5.6.2, §7.2.1), MUTANT (vertex-stage vectors): shades with L and V as the vertex stage passed them, interpolated and not renormalised; only the normal is renormalised.
#version 450

layout(location = 0) in vec3 objectNormal;
layout(location = 1) in vec3 toLight;
layout(location = 2) in vec3 toEye;

layout(std140, binding = 1) uniform PhongShade {
    vec3 diffuseColor;
    vec3 specularColor;
    float specularPower;
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    vec3 r = reflect(-toLight, n);
    vec3 diffuse = diffuseColor * max(dot(n, toLight), 0.0);
    vec3 specular = specularColor * pow(max(dot(r, toEye), 0.0), specularPower);
    fragColor = vec4(diffuse + specular, 1.0);
}
