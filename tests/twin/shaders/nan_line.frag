// Lambert per pixel (book §5.5) with a planted NaN: sqrt of N.L, negative where the surface faces away from the light.
#version 450

layout(location = 1) in vec3 objectNormal;   // from setup.vert

layout(std140, binding = 1) uniform Light {
    vec3 lightDirection;   // object space, unit, toward the light
};

layout(location = 0) out vec4 fragColor;

void main()
{
    vec3 n = normalize(objectNormal);
    float facing = dot(n, lightDirection);
    float soft = sqrt(facing);
    fragColor = vec4(vec3(soft), 1.0);
}
