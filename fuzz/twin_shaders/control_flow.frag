// twin_fuzzer seed: nested loops, break and continue, switch, short-circuit phis, calls with
// inout parameters, discard.
#version 450
layout(location = 0) in vec4 a;
layout(location = 1) flat in vec4 b;
layout(location = 0) out vec4 colour;

layout(std140, set = 0, binding = 0) uniform Block {
    int count;
    float scale;
    vec4 weights[4];
};

float accumulate(inout vec3 sum, float x, int steps) {
    for (int i = 0; i < steps; ++i) {
        if (x > 10.0) break;
        sum += vec3(x, x * x, float(i));
        x += 0.5;
    }
    return x;
}

int pick(int k) {
    switch (k & 3) {
        case 0: return 1;
        case 1:
        case 2: k += 3; break;
        default: return -1;
    }
    return k;
}

void main() {
    vec3 sum = vec3(0.0);
    int n = int(a.x * 4.0) + 3 + count;
    for (int i = 0; i < n; ++i) {
        if (i == 2) continue;
        int j = 0;
        while (j < i) {
            sum.x += weights[j & 3].x + 0.25;
            if (sum.x > 100.0) break;
            ++j;
        }
        do {
            sum.y += 1.0;
        } while (sum.y < float(i));
    }
    float x = accumulate(sum, a.y, pick(int(b.x * 8.0)) + 2);
    bool far = a.x > 0.5 && (a.y < 0.25 || x > 2.0);
    if (far && a.z > 0.9) discard;
    colour = vec4(sum * scale, far ? 1.0 : 0.5);
}
