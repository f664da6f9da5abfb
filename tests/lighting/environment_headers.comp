#version 460
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;
#include "device_host.h"
layout(binding = 0, r32ui) uniform readonly uimageBuffer envCdf;
layout(binding = 1, std430) buffer Out { vec4 o[]; };
#define VKRT_ENV_CDF(i) uintBitsToFloat(imageLoad(envCdf, int(i)).x)
#define VKRT_LOOP_CHARGE()  // the kernels charge their loop budget here (budget.glsl)
#include "environment_sampling.h"
void main() {
    uint i = gl_GlobalInvocationID.x;
    vec4 s = sampleEnvironment(64u, vec2(0.3, float(i) / 64.0));
    float p = environmentPdf(64u, s.xyz);
    CubeFacePoint q = cubeFacePoint(s.xyz);
    CubeTexelFootprint f = cubeTexelFootprint(q, 1024u);
    uvec3 b = cubeBorderSource(q.face, 0, 5, 1024u);
    o[i] = vec4(s.w, p, f.weight.x + float(f.first + b.x), cubeFaceRectSolidAngle(vec2(0), vec2(0.5)));
}
