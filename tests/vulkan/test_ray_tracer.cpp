// GpuRayTracer (trace_rays.comp) against the CPU traversal of the same BVH: closest hits and
// shadow (any-hit) queries on a scene with triangles, spheres, boxes and transformed instances.
#include <algorithm>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "gpu_build_options.h"
#include "gpu_ray_tracer.h"
#include "node_packing.h"
#include "vulkan_errors.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::VulkanTest;

// n triangles, each with its corners within `size` of a centre drawn from a cube of half-side
// `spread` (same draws in the same order as spelling the loop out, so scenes stay as they were).
void addRandomTriangles(std::mt19937& random, std::vector<bvh::PrimitiveInput>& group, int n, float spread, float size) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto point = [&] { return glm::vec3(u(random), u(random), u(random)); };
    for (int i = 0; i < n; ++i) {
        const glm::vec3 c = spread * point();
        group.push_back({gpu::PRIM_KIND_TRIANGLE, c + size * point(), c + size * point(), c + size * point()});
    }
}

bvh::SceneBvh randomScene(int maxLeafSize = 8, glm::vec3 offset = glm::vec3(0.0f), bvh::BuildOptions build = {}) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto point = [&] { return glm::vec3(u(random), u(random), u(random)); };
    std::vector<std::vector<bvh::PrimitiveInput>> groups(2);
    addRandomTriangles(random, groups[0], 300, 4.0f, 0.3f);
    for (int i = 0; i < 40; ++i) groups[0].push_back({gpu::PRIM_KIND_SPHERE, 4.0f * point(), glm::vec3(0.1f + 0.2f * std::abs(u(random)), 0, 0), {}});
    for (int i = 0; i < 40; ++i) {
        const glm::vec3 lo = 4.0f * point();
        groups[0].push_back({gpu::PRIM_KIND_BOX, lo, lo + glm::vec3(0.3f) + 0.2f * glm::abs(point()), {}});
    }
    for (int i = 0; i < 50; ++i) groups[1].push_back({gpu::PRIM_KIND_TRIANGLE, point(), point(), point()});
    for (auto& group : groups)
        for (bvh::PrimitiveInput& p : group) {
            p.a += offset;
            if (p.kind != gpu::PRIM_KIND_SPHERE) p.b += offset;  // a sphere's b.x is its radius
            if (p.kind == gpu::PRIM_KIND_TRIANGLE) p.c += offset;
        }
    const glm::mat4 a = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, 0.5f, -1.0f)), 0.7f, glm::vec3(0, 1, 1));
    const glm::mat4 b = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(-2.0f, -1.0f, 1.5f)), glm::vec3(0.5f, 2.0f, 1.0f));
    build.maxLeafSize = maxLeafSize;
    // A leaf cost far below a node's makes the SAH keep leaves as large as allowed.
    if (maxLeafSize > 8) build.intersectionCost = 0.05f;
    return bvh::buildSceneBvh(groups, {{0, glm::mat4(1.0f), gpu::MATERIAL_NONE}, {1, a, gpu::MATERIAL_NONE}, {1, b, gpu::MATERIAL_NONE}},
                              build);
}

std::vector<gpu::TraceRayInput> randomRays(std::size_t n, float tMax, glm::vec3 offset = glm::vec3(0.0f)) {
    std::mt19937 random(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<gpu::TraceRayInput> rays(n);
    for (auto& r : rays) {
        const glm::vec3 origin = offset + 6.0f * glm::vec3(u(random), u(random), u(random));
        const glm::vec3 target = offset + 3.0f * glm::vec3(u(random), u(random), u(random));
        r.origin = glm::vec4(origin, tMax);
        r.direction = glm::vec4(glm::normalize(target - origin), 0.0f);
    }
    return rays;
}

// Rays from points in a cube of half-side `from` towards points in one of half-side `to`; every
// other ray stops half-way, so shadow queries see hits and misses.
std::vector<gpu::TraceRayInput> raysAcross(std::mt19937& random, std::size_t n, float from, float to) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto point = [&] { return glm::vec3(u(random), u(random), u(random)); };
    std::vector<gpu::TraceRayInput> rays(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 origin = from * point(), target = to * point();
        rays[i].origin = glm::vec4(origin, i % 2 ? 0.5f * glm::length(target - origin) : 1e30f);
        rays[i].direction = glm::vec4(glm::normalize(target - origin), 0.0f);
    }
    return rays;
}

// GPU hits against the CPU traversal of the same rays. A disagreement: one hits and the other
// does not, or (closest hits) another primitive or instance. Agreeing closest hits must match t to
// 1e-5 relative plus 1e-6 of |origin|: the origin (up to ~28 from the world origin in these tests)
// is carried into each instance's space in float on both sides, a few ULP of |origin| apart (~1e-6
// seen), which dominates for rays that start next to a surface.
struct CpuComparison {
    int disagreements = 0;
    int cpuHits = 0;
    int instanceZeroHits = 0;  // closest hits the CPU finds in instance 0
};
// `gpuScene` is the tree the GPU traced when it is not the CPU's (each orders the primitives its
// own way): a primitive is then named by its instance and input index (SceneBvh::primSource).
CpuComparison compareWithCpu(const bvh::SceneBvh& scene, const bvh::SceneBvh& gpuScene,
                             const std::vector<gpu::TraceRayInput>& rays, const std::vector<gpu::TraceHitOutput>& hits,
                             bool anyHit) {
    CpuComparison c;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        const bvh::Ray ray{glm::vec3(rays[i].origin), glm::vec3(rays[i].direction), rays[i].origin.w};
        bvh::Hit hit;
        const bool cpuHit = anyHit ? bvh::intersectAny(scene, ray) : bvh::intersectClosest(scene, ray, hit);
        const bool gpuHit = hits[i].hit.x != gpu::TRACE_MISS;
        c.cpuHits += cpuHit;
        const bool samePrim = cpuHit && gpuHit && scene.primSource[hit.prim] == gpuScene.primSource[hits[i].hit.y];
        if (cpuHit != gpuHit || (!anyHit && cpuHit && (!samePrim || hit.instance != hits[i].hit.z))) {
            ++c.disagreements;
        } else if (!anyHit && cpuHit) {
            c.instanceZeroHits += hit.instance == 0;
            const float slack = 1e-5f * hit.t + 1e-6f * glm::length(glm::vec3(rays[i].origin));
            EXPECT_NEAR(glm::uintBitsToFloat(hits[i].hit.x), hit.t, slack) << "ray " << i;
        }
    }
    return c;
}
CpuComparison compareWithCpu(const bvh::SceneBvh& scene, const std::vector<gpu::TraceRayInput>& rays,
                             const std::vector<gpu::TraceHitOutput>& hits, bool anyHit) {
    return compareWithCpu(scene, scene, rays, hits, anyHit);
}

// The GPU and CPU traversals share the algorithms, not the arithmetic (the device may contract
// into FMAs), so a ray grazing an edge or a box corner can go either way: at most 0.2% of the
// rays may disagree on hit/miss or on which primitive is closest, and a shared hit's distance
// must agree to 1e-5 relative (a few ULP of t, far below any primitive's size).
// Leaves of up to 8 primitives (the builder's default) and of up to 15, the most a traversal
// stack entry can hold (device_host.h: LEAF_ENTRY_MAX_COUNT).
class RayTracerLeaves : public VulkanTest, public ::testing::WithParamInterface<int> {};

TEST_P(RayTracerLeaves, MatchesTheCpuTraversal) {
    const bvh::SceneBvh scene = randomScene(GetParam());
    std::uint32_t largestLeaf = 0;
    for (const bvh::BinaryNode& node : scene.nodes) largestLeaf = std::max({largestLeaf, node.link.z, node.link.w});
    std::cout << "largest leaf: " << largestLeaf << " primitives\n";
    // With the cheap intersection cost the build fills leaves to the limit, so the kernel's
    // leaf entries really carry the largest count they can encode.
    if (GetParam() > 8) {
        EXPECT_EQ(largestLeaf, static_cast<std::uint32_t>(GetParam()));
    }
    GpuRayTracer& tracer = rayTracer(scene);
    const std::vector<gpu::TraceRayInput> rays = randomRays(20000, 1e30f);

    GpuTraceStats stats;
    const auto closest = tracer.trace(rays, false, &stats);
    std::cout << "trace: " << rays.size() << " rays in " << stats.traceSeconds << " s, pipeline " << stats.pipelineSeconds << " s\n";
    int disagreements = 0, hitsSeen = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        bvh::Ray ray{glm::vec3(rays[i].origin), glm::vec3(rays[i].direction), rays[i].origin.w};
        bvh::Hit hit;
        const bool cpuHit = bvh::intersectClosest(scene, ray, hit);
        const bool gpuHit = closest[i].hit.x != 0xffffffffu;
        hitsSeen += cpuHit;
        if (cpuHit != gpuHit || (cpuHit && (hit.prim != closest[i].hit.y || hit.instance != closest[i].hit.z))) {
            ++disagreements;
            continue;
        }
        if (cpuHit) {
            EXPECT_NEAR(glm::uintBitsToFloat(closest[i].hit.x), hit.t, 1e-5f * hit.t) << "ray " << i;
        }
    }
    EXPECT_GT(hitsSeen, 2000) << "the rays should hit the scene often";
    EXPECT_LT(hitsSeen, 19000) << "and miss it sometimes";
    EXPECT_LE(disagreements, static_cast<int>(rays.size()) / 500);

    // Shadow rays with a finite tMax: any hit before it.
    std::vector<gpu::TraceRayInput> shadows = randomRays(20000, 4.0f);
    const auto any = tracer.trace(shadows, true);
    int anyDisagreements = 0, blocked = 0;
    for (std::size_t i = 0; i < shadows.size(); ++i) {
        bvh::Ray ray{glm::vec3(shadows[i].origin), glm::vec3(shadows[i].direction), shadows[i].origin.w};
        const bool cpu = bvh::intersectAny(scene, ray);
        blocked += cpu;
        anyDisagreements += cpu != (any[i].hit.x != 0xffffffffu);
    }
    EXPECT_GT(blocked, 500);
    EXPECT_LE(anyDisagreements, static_cast<int>(shadows.size()) / 500);
}

INSTANTIATE_TEST_SUITE_P(LeafSizes, RayTracerLeaves, ::testing::Values(8, static_cast<int>(gpu::LEAF_ENTRY_MAX_COUNT)));

// Geometry 10^4 from the origin, 100x its size: packing the nodes would loosen their boxes far
// beyond the primitives' size (node_packing.h), so they go up exact, and the kernel's other node
// layout must find the same hits as the CPU (tolerance as above). The offset translates the rays
// with the geometry; with instances a and b the shapes land elsewhere, which the CPU follows too.
TEST_F(VulkanTest, RayTracerMatchesTheCpuWithExactNodesFarFromTheOrigin) {
    const glm::vec3 offset(1e4f, -2e4f, 1e4f);
    const bvh::SceneBvh scene = randomScene(8, offset);
    const GpuNodes nodes = gpuNodes(scene);
    ASSERT_FALSE(nodes.packed) << "area growth " << nodes.areaGrowth;
    EXPECT_EQ(nodes.texels.size(), scene.nodes.size() * gpu::GPU_EXACT_NODE_TEXELS);
    GpuRayTracer& tracer = rayTracer(scene);
    const std::vector<gpu::TraceRayInput> rays = randomRays(20000, 1e30f, offset);
    const auto closest = tracer.trace(rays, false);
    int disagreements = 0, hitsSeen = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        bvh::Ray ray{glm::vec3(rays[i].origin), glm::vec3(rays[i].direction), rays[i].origin.w};
        bvh::Hit hit;
        const bool cpuHit = bvh::intersectClosest(scene, ray, hit);
        hitsSeen += cpuHit;
        disagreements += cpuHit != (closest[i].hit.x != 0xffffffffu) || (cpuHit && hit.prim != closest[i].hit.y);
    }
    EXPECT_GT(hitsSeen, 1000);
    EXPECT_LE(disagreements, static_cast<int>(rays.size()) / 500);
}

// traverse.glsl keeps the stack's top entries in registers and the rest in an array that only its
// main loop touches: a push with the registers full spills one, a pop with them empty refills one.
// Entering an instance pushes nothing: the walk tests each node with its own level's ray, so a
// top-level entry popped after an instance's last one must be tested with the world ray again.
// Many instances of a deep tree, crossed by long rays, take every one of those paths at both
// levels: the top level alone is deeper than the registers hold.
TEST_F(VulkanTest, RayTracerMatchesTheCpuThroughDeepStacksAndManyInstances) {
    std::mt19937 random(23);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto point = [&] { return glm::vec3(u(random), u(random), u(random)); };
    std::vector<std::vector<bvh::PrimitiveInput>> groups(1);
    addRandomTriangles(random, groups[0], 3000, 1.0f, 0.05f);
    std::vector<bvh::InstanceInput> instances;
    for (int i = 0; i < 300; ++i) {
        const glm::mat4 m = glm::rotate(glm::translate(glm::mat4(1.0f), 12.0f * point()), 3.0f * u(random), glm::normalize(point() + glm::vec3(0.0f, 0.0f, 1.5f)));
        instances.push_back({0, glm::scale(m, glm::vec3(0.5f + 0.3f * u(random))), gpu::MATERIAL_NONE});
    }
    const bvh::SceneBvh scene = bvh::buildSceneBvh(groups, instances, {});
    ASSERT_GE(scene.stats.topDepth, 8) << "the top level must be deeper than the 4 register entries";
    ASSERT_GE(scene.stats.bottomDepth, 8);

    GpuRayTracer& tracer = rayTracer(scene);
    const std::vector<gpu::TraceRayInput> rays = raysAcross(random, 20000, 16.0f, 10.0f);
    // Same tolerance as RayTracerLeaves (grazing rays may go either way on FMA contraction).
    for (const bool anyHit : {false, true}) {
        const CpuComparison c = compareWithCpu(scene, rays, tracer.trace(rays, anyHit), anyHit);
        EXPECT_GT(c.cpuHits, 2000) << (anyHit ? "shadow" : "closest");
        EXPECT_LT(c.cpuHits, 19000) << (anyHit ? "shadow" : "closest");
        EXPECT_LE(c.disagreements, static_cast<int>(rays.size()) / 500) << (anyHit ? "shadow" : "closest");
    }
}

// The loose shapes (group 0, instance 0 with the identity transform) are walked as part of the
// top level, their leaves tested with the world ray (node_packing.h, InlinedWorld), while other
// instances are entered: rays that cross both, in either order, must report the CPU's hits,
// instance indices included.
TEST_F(VulkanTest, RayTracerMatchesTheCpuWithTheWorldGroupInTheTopLevel) {
    std::mt19937 random(29);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto point = [&] { return glm::vec3(u(random), u(random), u(random)); };
    std::vector<std::vector<bvh::PrimitiveInput>> groups(2);
    addRandomTriangles(random, groups[0], 2000, 10.0f, 0.3f);
    for (int i = 0; i < 40; ++i) {  // loose spheres and boxes too: every kind takes the world ray
        const glm::vec3 c = 10.0f * point();
        groups[0].push_back({gpu::PRIM_KIND_SPHERE, c, glm::vec3(0.4f, 0.0f, 0.0f), glm::vec3(0.0f)});
        groups[0].push_back({gpu::PRIM_KIND_BOX, c + glm::vec3(0.5f), c + glm::vec3(0.9f), glm::vec3(0.0f)});
    }
    addRandomTriangles(random, groups[1], 500, 1.0f, 0.1f);
    std::vector<bvh::InstanceInput> instances{{0, glm::mat4(1.0f), gpu::MATERIAL_NONE}};
    for (int i = 0; i < 40; ++i) {
        const glm::mat4 m = glm::rotate(glm::translate(glm::mat4(1.0f), 9.0f * point()), 3.0f * u(random), glm::normalize(point() + glm::vec3(0, 0, 1.5f)));
        instances.push_back({1, glm::scale(m, glm::vec3(1.0f + 0.5f * u(random))), gpu::MATERIAL_NONE});
    }
    const bvh::SceneBvh scene = bvh::buildSceneBvh(groups, instances, {});
    ASSERT_TRUE(inlinedWorld(scene).inlined) << "the test needs the world group inlined";

    GpuRayTracer& tracer = rayTracer(scene);
    const std::vector<gpu::TraceRayInput> rays = raysAcross(random, 20000, 14.0f, 8.0f);
    for (const bool anyHit : {false, true}) {
        const CpuComparison c = compareWithCpu(scene, rays, tracer.trace(rays, anyHit), anyHit);
        // Same tolerance as the tests above (grazing rays may go either way on FMA contraction).
        EXPECT_LE(c.disagreements, static_cast<int>(rays.size()) / 500) << (anyHit ? "shadow" : "closest");
        if (!anyHit) {
            EXPECT_GT(c.instanceZeroHits, 2000);
            EXPECT_GT(c.cpuHits - c.instanceZeroHits, 500);
        }
    }
}

TEST_F(VulkanTest, RayTracerSplitsLargeRayListsIntoBatches) {
    const bvh::SceneBvh scene = randomScene();
    GpuTestHooks options;
    // Batches of 4096 rays, to keep the test quick. The hit buffer binds first: its view has one
    // R32UI texel per word and room for TRACE_HIT_WORDS_INSTANCED words per ray, and the cap allows
    // maxBytes / 16 texels per view (capLimits); 128 texels spare for the padding
    // (stableTexelBufferBytes), or the batch would shrink by a workgroup.
    options.maxBufferBytes = 16 * (4096 * gpu::TRACE_HIT_WORDS_INSTANCED + 128);
    GpuRayTracer& tracer = rayTracer(scene, options);
    ASSERT_EQ(tracer.maxRaysPerSubmission(), 4096u);
    const std::vector<gpu::TraceRayInput> rays = randomRays(tracer.maxRaysPerSubmission() + 1000, 1e30f);
    GpuTraceStats stats;
    const auto all = tracer.trace(rays, false, &stats);
    EXPECT_EQ(stats.submissions, 2u);
    // The second batch's rays come back in place: the same as tracing them alone.
    const auto tail = tracer.trace(std::span(rays).subspan(tracer.maxRaysPerSubmission()), false);
    ASSERT_EQ(tail.size(), 1000u);
    for (std::size_t i = 0; i < tail.size(); ++i) EXPECT_EQ(all[tracer.maxRaysPerSubmission() + i].hit, tail[i].hit);
}

// The kernel reports a ray it could not finish in its hit record (trace_rays.comp), and the tracer
// turns that into an error instead of returning a wrong hit: 80,000 coincident triangles all lie at
// the same distance, so a closest-hit ray must visit every leaf, far more loop passes than the
// per-ray budget (LOOP_BUDGET) allows. On lavapipe the driver's loop limiter ends it first (its
// count includes every inner loop's exit pass), on other drivers the budget does: either is an error.
TEST_F(VulkanTest, RayTracerReportsARayOverTheLoopBudget) {
    std::vector<std::vector<bvh::PrimitiveInput>> groups(1);
    for (int i = 0; i < 80000; ++i)
        groups[0].push_back({gpu::PRIM_KIND_TRIANGLE, glm::vec3(-1, -1, 0), glm::vec3(1, -1, 0), glm::vec3(0, 1, 0)});
    const bvh::SceneBvh scene = bvh::buildSceneBvh(groups, {{0, glm::mat4(1.0f), gpu::MATERIAL_NONE}}, {});
    GpuRayTracer& tracer = rayTracer(scene);
    const std::vector<gpu::TraceRayInput> rays{{glm::vec4(0.0f, 0.0f, -1.0f, 1e30f), glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)}};
    try {
        tracer.trace(rays, false);
        FAIL() << "a ray over the loop budget came back as a result";
    } catch (const GpuKernelError& e) {
        const std::string what = e.what();
        EXPECT_TRUE(what.find("needed more than") != std::string::npos || what.find("cut off") != std::string::npos) << what;
        EXPECT_NE(what.find("ray 0 of 1"), std::string::npos) << "the message names the ray: " << what;
    }
    // An any-hit query stops at the first triangle: well within the budget.
    EXPECT_NE(tracer.trace(rays, true)[0].hit.x, 0xffffffffu);
}

TEST(GpuRayTracer, RefusesABvhOverTheLimit) {
    const bvh::SceneBvh scene = randomScene();
    GpuTestHooks options;
    options.maxBufferBytes = scene.nodes.size() * sizeof(gpu::GpuBvhNode) - 16;  // one texel short of the packed nodes
    try {
        GpuRayTracer tracer(scene, {}, options);
        FAIL() << "accepted";
    } catch (const DeviceLimitExceeded& e) {
        EXPECT_NE(std::string(e.what()).find("BVH nodes"), std::string::npos) << e.what();
    }
}

// `vkrt` renders on the GPU from a tree built with the kernel's SAH constants (gpu_build_options.h)
// and on the CPU from one built with the CPU's, so the two trees must find the same surfaces. Each
// tree orders the primitives its own way: a hit is compared by its instance and its input
// primitive (SceneBvh::primSource). Tolerances as in RayTracerLeaves.MatchesTheCpuTraversal.
TEST_F(VulkanTest, TheGpuTreeFindsTheHitsOfTheCpuTree) {
    const bvh::SceneBvh cpuScene = randomScene();
    const bvh::SceneBvh gpuScene = randomScene(8, glm::vec3(0.0f), gpuBuildOptions());
    ASSERT_LT(gpuScene.nodes.size(), cpuScene.nodes.size()) << "the GPU's constants should give another, smaller tree";
    GpuRayTracer& tracer = rayTracer(gpuScene);
    const std::vector<gpu::TraceRayInput> rays = randomRays(20000, 1e30f);
    const CpuComparison closest = compareWithCpu(cpuScene, gpuScene, rays, tracer.trace(rays, false), false);
    EXPECT_GT(closest.cpuHits, 2000);
    EXPECT_LE(closest.disagreements, static_cast<int>(rays.size()) / 500);
    const std::vector<gpu::TraceRayInput> shadows = randomRays(20000, 4.0f);
    const CpuComparison any = compareWithCpu(cpuScene, gpuScene, shadows, tracer.trace(shadows, true), true);
    EXPECT_GT(any.cpuHits, 500);
    EXPECT_LE(any.disagreements, static_cast<int>(shadows.size()) / 500);
}

}  // namespace
}  // namespace vkrt
