// The toon original (Lambert through a ramp lookup, book §5.5 and Ch. 6's lookup textures) ported to GLSL 4.50: the correct port.
#version 450
layout(location = 0) in vec3 vNormal;
layout(location = 0) out vec4 colour;

layout(binding = 1) uniform Light {
    vec3 LightDir;
};
layout(binding = 2) uniform sampler2D ToonRamp;

void main()
{
    float nl = clamp(dot(normalize(vNormal), LightDir), 0.0, 1.0);
    colour = vec4(texture(ToonRamp, vec2(nl, 0.5)).rgb, 1.0);
}
