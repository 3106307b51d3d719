// twin_fuzzer seed: every image instruction the twin runs, on every dimension, combined and
// separate samplers, an array of samplers indexed per pixel.
#version 450
layout(location = 0) in vec4 uv;
layout(location = 0) out vec4 colour;

layout(set = 0, binding = 0) uniform sampler1D line;
layout(set = 0, binding = 1) uniform sampler2D flat2d;
layout(set = 0, binding = 2) uniform sampler3D volume;
layout(set = 0, binding = 3) uniform samplerCube cube;
layout(set = 0, binding = 4) uniform texture2D image;
layout(set = 0, binding = 5) uniform sampler state;
layout(set = 0, binding = 6) uniform sampler2D several[3];

void main() {
    vec4 c = texture(line, uv.x);
    c += texture(flat2d, uv.xy, 0.5);
    c += textureLod(flat2d, uv.yx, uv.z * 3.0);
    c += textureGrad(flat2d, uv.xy, vec2(0.1, 0.0), vec2(0.0, 0.3));
    c += textureProj(flat2d, vec3(uv.xy, uv.w + 0.5));
    c += texture(volume, uv.xyz);
    c += texture(cube, uv.xyz - 0.5);
    c += texture(sampler2D(image, state), uv.xy);
    c += texelFetch(flat2d, ivec2(uv.xy * 5.0) - 1, int(uv.z));
    c += texture(several[int(uv.x * 3.0) % 3], uv.xy);
    ivec2 size = textureSize(flat2d, 1);
    c.x += float(size.x + textureQueryLevels(flat2d));
    c.yz += textureQueryLod(flat2d, uv.xy);
    colour = c;
}
