// The textured original (Lambert with a texture, book §5.5) ported to GLSL 4.50: the correct port.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 1) in vec2 vUV;
layout(location = 0) out vec4 colour;

layout(binding = 1) uniform Light {
    vec3 LightDir;
};
layout(binding = 2) uniform sampler2D DiffuseMap;

void main()
{
    vec3 n = normalize(vNormal);
    colour = vec4(texture(DiffuseMap, vUV).rgb * clamp(dot(n, LightDir), 0.0, 1.0), 1.0);
}
