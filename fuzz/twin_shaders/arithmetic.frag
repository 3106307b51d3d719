// twin_fuzzer seed: matrices, integer and bit operations, packing, bitcasts, derivatives,
// built-ins, push constants, a read-only storage buffer and local arrays indexed per pixel.
#version 450
layout(location = 0) in vec4 v;
layout(location = 1) flat in ivec2 k;
layout(location = 0) out vec4 colour;

layout(push_constant) uniform Push { mat3 rotation; uint mask; } push;
layout(std430, set = 1, binding = 0) readonly buffer Data { vec4 items[]; } data;
layout(std140, set = 1, binding = 1) uniform Block { layout(row_major) mat4 m; ivec4 shifts; } block;

struct Pair { vec2 a; float b[3]; };

void main() {
    mat4 m = block.m * transpose(block.m) + outerProduct(v, v.wzyx);
    mat2 small = inverse(mat2(v.x + 2.0, v.y, v.z, v.w + 2.0));
    float det = determinant(m) + determinant(mat3(m));
    vec3 r = push.rotation * v.xyz + v.xyz * push.rotation;
    int i = k.x * 7 - k.y / 3 + (k.x % 5) + (k.y << block.shifts.x) + (k.x >> 2);
    uint u = uint(i) ^ push.mask | (uint(k.y) & 0xf0u);
    u += uint(findLSB(u)) + uint(findMSB(i)) + (u >> 3u) % 7u + u / 3u;
    float bits = intBitsToFloat(i & 0x3f7fffff) + uintBitsToFloat(u & 0x3f000000u) + float(floatBitsToInt(v.x) & 255);
    vec4 unpacked = unpackUnorm4x8(u) + unpackSnorm4x8(u) + vec4(unpackHalf2x16(packHalf2x16(v.xy)), 0.0, 0.0);
    unpacked.x += float(packUnorm4x8(v) & 255u) + float(packSnorm4x8(v) & 255u);
    vec4 d = dFdx(v) + dFdy(v) + fwidth(v) + dFdxFine(v) + dFdyCoarse(v) + fwidthCoarse(v);
    Pair p = Pair(v.xy, float[3](v.z, v.w, det));
    float local[5] = float[5](1.0, 2.0, 3.0, 4.0, 5.0);
    local[clamp(i, 0, 4)] += p.b[k.x & 1];
    vec4 w = v;
    w[k.y & 3] = local[(k.x + 9) % 5];
    vec4 item = data.items[k.x & 7];
    vec4 g = vec4(pow(abs(v.x), 2.2), exp2(v.y), log(abs(v.z) + 1.0), inversesqrt(v.w + 2.0));
    g += vec4(smoothstep(0.2, 0.8, v.x), step(0.5, v.y), mix(v.z, v.w, 0.3), fma(v.x, v.y, v.z));
    g += vec4(reflect(v.xyz, normalize(r + 1.0)), length(cross(v.xyz, r)));
    g += vec4(refract(normalize(v.xyz + 1.0), vec3(0.0, 0.0, 1.0), 0.7), distance(v, w));
    g += vec4(sin(v.x), atan(v.y, v.z), sinh(v.w), modf(v.x * 3.0, g.w));
    g += vec4(frexp(v.y + 1.5, i), ldexp(v.z, k.x), roundEven(v.w * 5.0), trunc(v.x * 3.0));
    g += any(isnan(v / v.x)) || any(isinf(1.0 / v)) || gl_FrontFacing || gl_HelperInvocation ? vec4(1.0) : vec4(0.0);
    colour = g + d + unpacked + item + vec4(small[0], gl_FragCoord.xy) + vec4(bits + float(u), 0.0, 0.0, 0.0) + w;
}
