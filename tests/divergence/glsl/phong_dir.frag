// Phong from a directional light with diffuse, specular and ambient colours (book §5.5, §5.6.2, §5.6.4), GLSL 4.50: the original.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec3 vView;
layout(location = 0) out vec4 fragColour;

layout(binding = 1) uniform Material {
    vec3 LightDirection;    // object space, unit, toward the light
    vec3 DiffuseColour;
    vec3 SpecularColour;
    vec3 AmbientColour;
    float SpecularPower;
};

void main()
{
    vec3 N = normalize(vNormal);
    vec3 V = normalize(vView);
    vec3 L = LightDirection;
    float NdotL = dot(N, L);
    vec3 R = reflect(-L, N);
    float RdotV = max(dot(R, V), 0.0);
    float spec = NdotL > 0.0 ? pow(RdotV, SpecularPower) : 0.0;
    vec3 colour = AmbientColour + DiffuseColour * max(NdotL, 0.0) + SpecularColour * spec;
    fragColour = vec4(colour, 1.0);
}
