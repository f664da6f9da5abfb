// The build's output must not depend on the number of threads (bit-identical arrays), nor the GPU
// arrays on whether the CPU's 8-wide copy is built.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "scene_gen.h"

namespace vkrt::bvh::test {
namespace {

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

TEST(Determinism, ThreadCountDoesNotChangeTheResult) {
    std::mt19937 rng(21);
    TestScene scene;
    // A group large enough for the parallel top phase and parallel binning, small groups built
    // side by side, and enough instances for a real top level.
    scene.groups.push_back(randomTriangles(rng, 200000, 100.0f, 0.5f));
    for (int g = 0; g < 12; ++g) scene.groups.push_back(randomSpheresAndBoxes(rng, 500 + 300 * g, 10.0f, 0.5f));
    for (std::uint32_t g = 0; g < scene.groups.size(); ++g)
        scene.instances.push_back({g, randomTransform(rng, 100.0f, g % 2 == 0), gpu::MATERIAL_NONE});
    BuildOptions options;
    options.threads = 1;
    const SceneBvh reference = buildSceneBvh(scene.groups, scene.instances, options);
    for (int threads : {2, 3, 4, 7}) {
        options.threads = threads;
        const SceneBvh bvh = buildSceneBvh(scene.groups, scene.instances, options);
        EXPECT_TRUE(sameBytes(bvh.nodes, reference.nodes)) << threads << " threads";
        EXPECT_TRUE(sameBytes(bvh.prims, reference.prims)) << threads << " threads";
        EXPECT_TRUE(sameBytes(bvh.primSource, reference.primSource)) << threads << " threads";
        EXPECT_TRUE(sameBytes(bvh.instances, reference.instances)) << threads << " threads";
        EXPECT_TRUE(sameBytes(bvh.cpu.nodes, reference.cpu.nodes)) << threads << " threads (8-wide copy)";
        EXPECT_EQ(bvh.cpu.groupRoots, reference.cpu.groupRoots);
        EXPECT_TRUE(sameBytes(bvh.cpu.triangles.groups, reference.cpu.triangles.groups)) << threads << " threads (triangle groups)";
        EXPECT_EQ(bvh.cpu.triangles.leafGroup, reference.cpu.triangles.leafGroup);
        EXPECT_EQ(bvh.topRoot, reference.topRoot);
        EXPECT_EQ(bvh.stats.sahCost, reference.stats.sahCost);
    }
}

// A triangle soup and a group of spheres and boxes, each placed by a random instance.
TestScene meshBesideShapes(unsigned seed, std::size_t triangles, std::size_t shapes) {
    std::mt19937 rng(seed);
    TestScene scene;
    scene.groups.push_back(randomTriangles(rng, triangles, 50.0f, 0.5f));
    scene.groups.push_back(randomSpheresAndBoxes(rng, shapes, 10.0f, 0.5f));
    for (std::uint32_t g = 0; g < scene.groups.size(); ++g)
        scene.instances.push_back({g, randomTransform(rng, 50.0f, g == 0), gpu::MATERIAL_NONE});
    return scene;
}

// A group below 32K primitives holding most of the scene is built with the whole pool (its top
// phase splits ranges above 8K references across threads); small groups beside it are not.
TEST(Determinism, MidSizedGroupHoldingMostOfTheSceneDoesNotDependOnThreads) {
    const TestScene scene = meshBesideShapes(5, 20000, 3000);
    BuildOptions options;
    options.threads = 1;
    const SceneBvh reference = buildSceneBvh(scene.groups, scene.instances, options);
    for (int threads : {2, 3}) {
        options.threads = threads;
        const SceneBvh bvh = buildSceneBvh(scene.groups, scene.instances, options);
        EXPECT_TRUE(sameBytes(bvh.nodes, reference.nodes)) << threads << " threads";
        EXPECT_TRUE(sameBytes(bvh.prims, reference.prims)) << threads << " threads";
        EXPECT_TRUE(sameBytes(bvh.cpu.nodes, reference.cpu.nodes)) << threads << " threads (8-wide copy)";
    }
}

// BuildOptions::cpuTraversal = false skips only the 8-wide copy: what the GPU path uploads is the
// same, and CPU traversal of such a BVH fails loudly instead of reporting no hits.
TEST(Determinism, SkippingTheCpuCopyLeavesTheGpuArraysUnchanged) {
    const TestScene scene = meshBesideShapes(8, 40000, 2000);
    BuildOptions options;
    options.threads = 2;
    const SceneBvh full = buildSceneBvh(scene.groups, scene.instances, options);
    options.cpuTraversal = false;
    const SceneBvh gpuOnly = buildSceneBvh(scene.groups, scene.instances, options);
    EXPECT_TRUE(full.cpu.built);
    EXPECT_FALSE(gpuOnly.cpu.built);
    EXPECT_TRUE(gpuOnly.cpu.nodes.empty());
    EXPECT_TRUE(sameBytes(gpuOnly.nodes, full.nodes));
    EXPECT_TRUE(sameBytes(gpuOnly.prims, full.prims));
    EXPECT_TRUE(sameBytes(gpuOnly.primSource, full.primSource));
    EXPECT_TRUE(sameBytes(gpuOnly.instances, full.instances));
    EXPECT_EQ(gpuOnly.topRoot, full.topRoot);
    EXPECT_EQ(gpuOnly.stats.sahCost, full.stats.sahCost);
    EXPECT_EQ(gpuOnly.stats.bytes, full.stats.bytes);
    EXPECT_EQ(gpuOnly.stats.cpuCopySeconds, 0.0);
    const Ray ray{{0.0f, 0.0f, 200.0f}, {0.0f, 0.0f, -1.0f}};
    Hit hit;
    EXPECT_THROW(intersectClosest(gpuOnly, ray, hit), std::logic_error);
    EXPECT_THROW(intersectAny(gpuOnly, ray), std::logic_error);
    EXPECT_NO_THROW(intersectClosest(full, ray, hit));
}

}  // namespace
}  // namespace vkrt::bvh::test
