// twin_fuzzer seed: mediump values (RelaxedPrecision), which the half twin rounds to binary16.
#version 450
precision mediump float;
precision mediump int;
layout(location = 0) in vec4 v;
layout(location = 0) out vec4 colour;
layout(set = 0, binding = 2) uniform mediump sampler2D tex;

void main() {
    highp vec4 h = v * 1000.0;
    vec4 m = v * 1000.0 + 0.001;
    float s = 0.0;
    for (int i = 0; i < 40; ++i) s += m.x * 0.01 + texture(tex, v.xy + float(i) * 0.01).x;
    colour = vec4(m.xy - h.xy, s, normalize(m).w);
}
