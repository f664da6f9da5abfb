#version 460
// Test kernel for lavapipe's loop limiter (../shared/LAVAPIPE.md): counts the iterations a loop
// really runs. The increment is read from a buffer so the compiler cannot replace the loop by a
// closed form. Mode 0: one loop of n iterations. Mode 1: two loops of n iterations one after the
// other (does the limit count per loop or per invocation?).
layout(local_size_x = 1) in;

layout(std430, set = 0, binding = 0) buffer Counts {
    uint step[4];    // all 1, written by the host
    uint first;      // iterations the first loop ran
    uint second;     // iterations the second loop ran (mode 1)
};
layout(push_constant) uniform Push {
    uint n;
    uint mode;
} pc;

void main() {
    uint count = 0u;
    for (uint i = 0u; i < pc.n; ++i) count += step[i & 3u];
    first = count;
    if (pc.mode == 1u) {
        uint count2 = 0u;
        for (uint i = 0u; i < pc.n; ++i) count2 += step[(i + 1u) & 3u];
        second = count2;
    }
}
