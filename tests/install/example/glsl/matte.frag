// The example project's matte surface: albedo times the cosine toward the light, per pixel.
#version 450

layout(location = 0) in vec3 surfaceNormal;

layout(std140, binding = 1) uniform Surface {
    vec3 towardLight;   // object space, unit length
    vec3 albedo;
};

layout(location = 0) out vec4 color;

void main()
{
    float cosine = max(dot(normalize(surfaceNormal), towardLight), 0.0);
    color = vec4(albedo * cosine, 1.0);
}
