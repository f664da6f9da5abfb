#include "sample_batching.h"

#include <algorithm>
#include <limits>

#include "device_host.h"

namespace vkrt {

namespace {

// Passes of one traversal (shaders/traverse.glsl) through a tree of P primitives, every loop's
// exit pass included: walk passes <= P (one per inner node, and there are fewer inner nodes than
// primitives); main-loop rounds <= 3P + 2 (a leaf, a spill or a refill each, and the last), each
// with one walk exit; leaf passes <= P, plus an exit per leaf (<= P + 1); the main loop's exit.
// In all 9P + 6.
std::uint64_t treePasses(std::uint64_t prims) { return 9 * prims + 6; }

// a * b, or the largest value when it would not fit: deep dielectric trees, many light samples
// and large meshes multiply up, and a product that wrapped around would look small and batch.
std::uint64_t saturatingProduct(std::uint64_t a, std::uint64_t b) {
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    return (b != 0 && a > kMax / b) ? kMax : a * b;
}
std::uint64_t saturatingSum(std::uint64_t a, std::uint64_t b) {
    constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
    return a > kMax - b ? kMax : a + b;
}

}  // namespace

std::uint64_t sampleLoopBound(const Scene& scene, const bvh::SceneBvh& bvh, const FeatureSet& features,
                              const RenderOptions& options) {
    // One traversal: the top level (one leaf per instance), then each instance's group whole.
    std::uint64_t traversal = treePasses(bvh.instances.size());
    for (const gpu::Instance& instance : bvh.instances) traversal += treePasses(bvh.groups.at(gpu::instanceGroup(instance.info)).primCount);

    // Shadow rays per hit: one per point light, lightSamples per area light.
    const auto lightSamples = static_cast<std::uint64_t>(std::max(options.lightSamples, 1));
    std::uint64_t shadowRays = 0;
    for (const Light& light : scene.lights) shadowRays += light.type == LightType::Area ? lightSamples : 1;
    const auto glossSamples = static_cast<std::uint64_t>(std::max(options.glossSamples, 1));

    // Rays per sample: the camera ray alone; or, for each of the primary hit's gloss samples, a
    // chain of maxDepth reflections (mirrors, glazes: one ray per hit), or a tree in which every
    // hit emits at most two rays (dielectrics), maxDepth levels deep.
    std::uint64_t rays = 1;
    if (features.maxDepth > 0) {
        const std::uint64_t perGlossSample =
            features.dielectric ? (features.maxDepth + 1 >= 63 ? std::numeric_limits<std::uint64_t>::max()
                                                                 : std::uint64_t{1} << (features.maxDepth + 1))
                                : std::uint64_t{features.maxDepth} + 1;
        rays = saturatingProduct(glossSamples, perGlossSample);
    }

    // Per ray: its traversals, the light and gloss loops, and the sample grid's cycle walks
    // (sampling.h permuteIndex: fewer than two rounds expected; 8 allowed per sample drawn).
    // Scene sizes keep these sums far from overflow; the products with `rays` may not be.
    const std::uint64_t samplesDrawn = shadowRays + glossSamples + 1;
    const std::uint64_t perRay = saturatingSum(saturatingProduct(1 + shadowRays, traversal),
                                               shadowRays + glossSamples + 8 * samplesDrawn + 8);
    return saturatingSum(saturatingProduct(rays, perRay), 8);
}

std::uint32_t samplesPerDispatch(std::uint64_t sampleBound, std::uint32_t samplesPerPixel, std::uint32_t forced,
                                 std::uint64_t lockstepFactor) {
    const std::uint32_t most = std::max<std::uint32_t>(1, samplesPerPixel);
    if (forced > 0) return std::min(forced, most);
    const std::uint64_t fit = gpu::LOOP_BUDGET / (std::max<std::uint64_t>(sampleBound, 1) * std::max<std::uint64_t>(lockstepFactor, 1));
    if (fit < kMinSamplesPerDispatch) return 1;
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(fit, std::min(kMaxSamplesPerDispatch, most)));
}

}  // namespace vkrt
