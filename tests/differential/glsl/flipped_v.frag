// The textured original (Lambert with a texture, book §5.5) ported to GLSL 4.50: with one planted convention error: v flipped (GL's bottom-up image rows taken for D3D's top-down ones).
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
    vec2 uv = vec2(vUV.x, 1.0 - vUV.y);   // planted: flips v
    colour = vec4(texture(DiffuseMap, uv).rgb * clamp(dot(n, LightDir), 0.0, 1.0), 1.0);
}
