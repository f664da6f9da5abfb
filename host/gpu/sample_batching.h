// How many samples of its pixel one invocation of render.comp computes. One sample per dispatch
// costs a cheap scene most of its time outside the path: the pixel's running sum is loaded and
// stored (each stored word a loop over the 8 lanes on lavapipe), and the block mapping, the
// sample key and the failure reports run again. A dispatch of k samples pays them once, and adds
// the k samples to the loaded sum one by one in sample order, so the image is bit-identical to
// k = 1 (tests/vulkan/test_sample_batching.cpp).
//
// k is bounded by lavapipe's loop limiter, which counts every loop pass of an invocation (all its
// samples) and cuts the invocation off at 65,535: k is the largest count (at most
// kMaxSamplesPerDispatch) whose worst case, from sampleLoopBound, stays under LOOP_BUDGET with a
// factor for lockstep (a group of 8 lanes runs a loop while any lane needs it). Scenes whose bound
// is large (meshes, dielectrics, many lights) keep k = 1.
#pragma once

#include <cstdint>

#include "bvh.h"
#include "feature_set.h"
#include "render_options.h"
#include "scene.h"

namespace vkrt {

// The largest k: 8 takes the per-dispatch work out of cheap scenes' time, while a dispatch stays
// short enough for the planner's submissions (docs/lab/2026-12-02-lavapipe-kernel.md).
constexpr std::uint32_t kMaxSamplesPerDispatch = 8;

// Below this k, one sample per dispatch: the loop around the path costs about what a few samples
// save (docs/BENCHMARKS.md, "Tried and not kept").
constexpr std::uint32_t kMinSamplesPerDispatch = 4;

// A group of 8 lanes may pass a loop more often than its busiest lane, but each of its passes is
// a pass (an iteration or the exit) of at least one of its lanes: at most the 8 lanes' sum. Only
// lavapipe's limiter counts a group's passes (DeviceInfo::loopLimiter); elsewhere the kernel's own
// budget counts one lane's, and the factor is 1 (gpu_renderer.cpp).
constexpr std::uint64_t kLockstepFactor = 8;

// An upper bound on the loop passes (every loop of render.comp, budget-charged or not) of one
// lane for one sample: camera and secondary rays (a reflection chain or a dielectric tree of
// maxDepth levels, times the gloss fan-out), each a closest-hit traversal plus one shadow
// traversal per light sample, and
// every traversal at most three passes per node and primitive it could meet (the top level, and
// every instance's whole group).
std::uint64_t sampleLoopBound(const Scene& scene, const bvh::SceneBvh& bvh, const FeatureSet& features,
                              const RenderOptions& options);

// k for a render: the bound's k (1 below kMinSamplesPerDispatch), or `forced` (tests) when
// non-zero; never more than the samples.
std::uint32_t samplesPerDispatch(std::uint64_t sampleBound, std::uint32_t samplesPerPixel, std::uint32_t forced = 0,
                                 std::uint64_t lockstepFactor = kLockstepFactor);

// A render's samples in dispatch passes of k: pass p computes samples [first(p), first(p) + count(p)).
struct SampleBatching {
    std::uint32_t samplesPerPixel = 1;
    std::uint32_t perDispatch = 1;  // k

    std::uint32_t passes() const { return (samplesPerPixel + perDispatch - 1) / perDispatch; }
    std::uint32_t first(std::uint32_t pass) const { return pass * perDispatch; }
    std::uint32_t count(std::uint32_t pass) const {
        const std::uint32_t f = first(pass);
        return samplesPerPixel - f < perDispatch ? samplesPerPixel - f : perDispatch;
    }
};

}  // namespace vkrt
