// Lambert diffuse per pixel (book §5.5, §7.1.2): unpack the interpolated normal from the vertex colour, renormalise, D * max(0, N.L).
#version 450

layout(location = 0) in vec3 vPacked;

layout(std140, binding = 1) uniform Light {
    vec3 uLightDir;   // object space, unit, toward the light
    vec3 uDiffuse;
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(vPacked * 2.0 - 1.0);
    fragColor = vec4(uDiffuse * max(dot(n, uLightDir), 0.0), 1.0);
}
