// The 48-byte nodes the kernels read (host/vulkan/node_packing.h): every child's box read back
// contains the builder's box and is looser by at most the documented 2 * 2^bits ulp, and every
// child's entry read back is the one the builder's link and count mean. No device needed.
#include <bit>
#include <cfloat>
#include <cmath>
#include <random>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "node_layout.h"
#include "node_packing.h"

namespace vkrt {
namespace {

std::uint32_t bitsOf(float f) { return std::bit_cast<std::uint32_t>(f); }
float floatOf(std::uint32_t u) { return std::bit_cast<float>(u); }

// Distance in representable floats between a and b (same sign or across zero).
std::int64_t ulpsBetween(float a, float b) {
    auto ordered = [](float f) {
        const std::uint32_t u = bitsOf(f);
        return (u & 0x80000000u) ? -static_cast<std::int64_t>(u & 0x7fffffffu) : static_cast<std::int64_t>(u);
    };
    return std::llabs(ordered(a) - ordered(b));
}

void expectRoundedDown(float value, std::uint32_t payload, unsigned bits) {
    const float r = floatOf(roundDownWithLowBits(value, payload, bits));
    EXPECT_LE(r, value) << value;
    EXPECT_EQ(roundDownWithLowBits(value, payload, bits) & ((1u << bits) - 1u), payload) << value;
    // The nearest such float: fewer than two steps of 2^bits patterns below (at most one when
    // both are on the same side of zero).
    EXPECT_LT(ulpsBetween(r, value), 2 << bits) << value << " -> " << r;
    const float u = floatOf(roundUpWithLowBits(value, payload, bits));
    EXPECT_GE(u, value) << value;
    EXPECT_EQ(roundUpWithLowBits(value, payload, bits) & ((1u << bits) - 1u), payload) << value;
    EXPECT_LT(ulpsBetween(u, value), 2 << bits) << value << " -> " << u;
}

TEST(NodePacking, RoundingOutwardKeepsThePayloadAndStaysClose) {
    std::mt19937 random(3);
    std::uniform_int_distribution<std::uint32_t> payload6(0, 63), payload4(0, 15);
    std::uniform_real_distribution<float> mantissa(-1.0f, 1.0f);
    std::uniform_int_distribution<int> exponent(-140, 120);
    for (int i = 0; i < 20000; ++i) {
        const float value = std::ldexp(mantissa(random), exponent(random));  // denormals included
        expectRoundedDown(value, payload6(random), 6);
        expectRoundedDown(value, payload4(random), 4);
    }
    for (float v : {0.0f, -0.0f, FLT_MIN, -FLT_MIN, 1.0f, -1.0f, 1e-45f, -1e-45f, 3.0e38f, -3.0e38f})
        for (std::uint32_t p : {0u, 1u, 31u, 63u}) expectRoundedDown(v, p, 6);
}

TEST(NodePacking, RoundingRefusesBoundsWithNoFloatOutside) {
    EXPECT_THROW(roundDownWithLowBits(-INFINITY, 1, 6), std::invalid_argument);
    EXPECT_THROW(roundDownWithLowBits(NAN, 1, 6), std::invalid_argument);
    EXPECT_THROW(roundDownWithLowBits(-FLT_MAX, 1, 6), std::invalid_argument);  // nothing finite below it with payload 1
    EXPECT_THROW(roundUpWithLowBits(FLT_MAX, 1, 6), std::invalid_argument);
    // The empty child's box (lo = +FLT_MAX, hi = -FLT_MAX) rounds inward there, which is fine.
    EXPECT_NO_THROW(roundDownWithLowBits(FLT_MAX, 63, 6));
    EXPECT_NO_THROW(roundUpWithLowBits(-FLT_MAX, 63, 6));
}

bvh::SceneBvh instancedScene(float offset) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    auto point = [&] { return glm::vec3(offset) + glm::vec3(u(random), u(random), u(random)); };
    std::vector<std::vector<bvh::PrimitiveInput>> groups(2);
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 c = point();
        groups[0].push_back({gpu::PRIM_KIND_TRIANGLE, c, c + 0.05f * (point() - offset), c + 0.05f * (point() - offset)});
    }
    for (int i = 0; i < 30; ++i) groups[1].push_back({gpu::PRIM_KIND_SPHERE, point(), glm::vec3(0.05f, 0, 0), {}});
    std::vector<bvh::InstanceInput> instances;
    for (int i = 0; i < 20; ++i)
        instances.push_back({static_cast<std::uint32_t>(i % 2), glm::translate(glm::mat4(1.0f), glm::vec3(3.0f * i, 0, 0)),
                             gpu::MATERIAL_NONE});
    return bvh::buildSceneBvh(groups, instances, {});
}

TEST(NodePacking, PackedNodesHoldTheBuildersEntriesAndContainItsBoxes) {
    for (float offset : {0.0f, 1e5f, -3e-3f}) {
        const bvh::SceneBvh scene = instancedScene(offset);
        const std::vector<gpu::GpuBvhNode> packed = packNodes(scene);
        ASSERT_EQ(packed.size(), scene.nodes.size());
        // Which nodes are top-level, walked independently of packNodes.
        std::vector<bool> top(scene.nodes.size(), false);
        std::vector<std::uint32_t> pending{scene.topRoot};
        int leaves = 0, instanceLeaves = 0, inner = 0;
        while (!pending.empty()) {
            const std::uint32_t i = pending.back();
            pending.pop_back();
            top[i] = true;
            for (int k = 0; k < 2; ++k)
                if (bvh::childIsInner(scene.nodes[i], k)) pending.push_back(bvh::childLink(scene.nodes[i], k));
        }
        for (std::size_t i = 0; i < packed.size(); ++i) {
            const bvh::BinaryNode& node = scene.nodes[i];
            for (int k = 0; k < 2; ++k) {
                const std::uint32_t link = node.link[k], count = node.link[2 + k];
                const std::uint32_t entry = packedChildEntry(packed[i], k);
                if (count == 0 && link == bvh::NODE_NONE) {
                    EXPECT_EQ(entry, gpu::ENTRY_NONE);
                    continue;
                }
                if (count == 0) {
                    EXPECT_EQ(entry, link * gpu::GPU_NODE_TEXELS);
                    ++inner;
                } else if (top[i]) {
                    EXPECT_EQ(entry, gpu::ENTRY_INSTANCE_BIT | link);
                    ++instanceLeaves;
                } else {
                    EXPECT_EQ(entry, gpu::ENTRY_LEAF_BIT | (link << 4) | count);
                    ++leaves;
                }
                const bvh::Aabb exact = bvh::childBox(node, k);
                const bvh::Aabb box = packedChildBox(packed[i], k);
                EXPECT_TRUE(box.contains(exact));
                for (int axis = 0; axis < 3; ++axis) {
                    const int bits = axis < 2 ? gpu::NODE_ENTRY_XY_BITS : gpu::NODE_ENTRY_Z_BITS;
                    EXPECT_LT(ulpsBetween(box.lo[axis], exact.lo[axis]), 2 << bits);
                    EXPECT_LT(ulpsBetween(box.hi[axis], exact.hi[axis]), 2 << bits);
                }
            }
        }
        // The scene exercises every kind of entry.
        EXPECT_GT(inner, 0);
        EXPECT_GT(leaves, 0);
        EXPECT_EQ(instanceLeaves, 20);
    }
}

// The layout choice: near its origin a mesh's boxes barely grow, so the nodes go up packed; the
// same mesh 10^4 away (100x its size) would get boxes far larger than its triangles, so they go
// up exact: the builder's bits, with the ready entries in the fourth texel.
TEST(NodePacking, FarFromItsOriginGeometryKeepsTheExactLayout) {
    const bvh::SceneBvh nearScene = instancedScene(0.0f);
    const GpuNodes nearNodes = gpuNodes(nearScene);
    EXPECT_TRUE(nearNodes.packed);
    EXPECT_LT(nearNodes.areaGrowth, 1.001);
    EXPECT_EQ(nearNodes.texels.size(), nearScene.nodes.size() * gpu::GPU_NODE_TEXELS);

    const bvh::SceneBvh farScene = instancedScene(1e4f);
    const GpuNodes farNodes = gpuNodes(farScene);
    EXPECT_FALSE(farNodes.packed);
    EXPECT_GT(farNodes.areaGrowth, kMaxPackedAreaGrowth);
    ASSERT_EQ(farNodes.texels.size(), farScene.nodes.size() * gpu::GPU_EXACT_NODE_TEXELS);
    const std::vector<bool> top = topLevelNodes(farScene);
    for (std::size_t i = 0; i < farScene.nodes.size(); ++i) {
        const bvh::BinaryNode& node = farScene.nodes[i];
        const glm::uvec4* t = &farNodes.texels[i * gpu::GPU_EXACT_NODE_TEXELS];
        EXPECT_EQ(t[0], node.xy0);
        EXPECT_EQ(t[1], node.xy1);
        EXPECT_EQ(t[2], node.z01);
        EXPECT_EQ(t[3], glm::uvec4(childStackEntry(node, 0, top[i], gpu::GPU_EXACT_NODE_TEXELS), childStackEntry(node, 1, top[i], gpu::GPU_EXACT_NODE_TEXELS), 0u, 0u));
    }
}

// A box reaching within 2^6 ulp of the largest float has no outward neighbour carrying the entry
// bits: the scene goes up exact instead of failing.
TEST(NodePacking, BoundsAtTheLargestFloatKeepTheExactLayout) {
    std::vector<std::vector<bvh::PrimitiveInput>> groups(1);
    groups[0].push_back({gpu::PRIM_KIND_BOX, glm::vec3(0.0f), glm::vec3(1.0f), {}});
    groups[0].push_back({gpu::PRIM_KIND_BOX, glm::vec3(2.0f), glm::vec3(FLT_MAX), {}});
    const bvh::SceneBvh scene = bvh::buildSceneBvh(groups, {{0, glm::mat4(1.0f), gpu::MATERIAL_NONE}}, {});
    EXPECT_THROW(packNodes(scene), std::invalid_argument);
    GpuNodes nodes;
    ASSERT_NO_THROW(nodes = gpuNodes(scene));
    EXPECT_FALSE(nodes.packed);
    EXPECT_EQ(nodes.areaGrowth, INFINITY);
    EXPECT_EQ(nodes.texels.size(), scene.nodes.size() * gpu::GPU_EXACT_NODE_TEXELS);
}

// The kernel tells a top-level node by its index (at or after the top-level root: SceneBvh keeps
// the top level last); a BVH that broke that order would walk bottom-level nodes with the world
// ray, so the upload refuses it.
TEST(NodePacking, TheTopLevelMustComeLast) {
    std::vector<std::vector<bvh::PrimitiveInput>> groups(1);
    for (int i = 0; i < 40; ++i) {
        const glm::vec3 c(float(i), 0.0f, 0.0f);
        groups[0].push_back({gpu::PRIM_KIND_TRIANGLE, c, c + glm::vec3(1, 0, 0), c + glm::vec3(0, 1, 0)});
    }
    std::vector<bvh::InstanceInput> instances;
    for (int i = 0; i < 6; ++i)
        instances.push_back({0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 5.0f * float(i), 0.0f)), gpu::MATERIAL_NONE});
    bvh::SceneBvh scene = bvh::buildSceneBvh(groups, instances, {});
    ASSERT_GT(scene.nodes.size() - scene.topRoot, 1u) << "the top level must have inner nodes of its own";
    EXPECT_NO_THROW(checkTopLevelLast(scene));
    EXPECT_NO_THROW(gpuNodes(scene));
    // Move the top level's root to the front: nodes keep their links, the order breaks.
    const std::uint32_t root = scene.topRoot;
    std::swap(scene.nodes[0], scene.nodes[root]);
    for (bvh::BinaryNode& node : scene.nodes)
        for (int k = 0; k < 2; ++k)
            if (bvh::childIsInner(node, k)) {
                std::uint32_t& link = node.link[k];
                link = link == 0 ? root : (link == root ? 0 : link);
            }
    for (bvh::GroupRange& group : scene.groups)
        if (group.rootNode == 0) group.rootNode = root;
    for (gpu::Instance& instance : scene.instances)
        if (instance.info.x == 0) instance.info.x = root;
    scene.topRoot = 0;
    EXPECT_THROW(checkTopLevelLast(scene), std::logic_error);
    EXPECT_THROW(gpuNodes(scene), std::logic_error);
}

// A scene as scene_accel.cpp builds it: group 0 the loose shapes under instance 0 (identity),
// group 1 a prototype placed by two transformed instances.
bvh::SceneBvh worldAndPrototypeScene(const glm::mat4& worldTransform, std::uint32_t secondInstanceGroup,
                                     glm::vec3 offset = glm::vec3(0.0f)) {
    std::vector<std::vector<bvh::PrimitiveInput>> groups(2);
    for (int i = 0; i < 30; ++i) {
        const glm::vec3 c = offset + glm::vec3(float(i), 0.0f, 0.0f);
        groups[0].push_back({gpu::PRIM_KIND_TRIANGLE, c, c + glm::vec3(1, 0, 0), c + glm::vec3(0, 1, 0)});
        groups[1].push_back({gpu::PRIM_KIND_TRIANGLE, c, c + glm::vec3(0, 0, 1), c + glm::vec3(0, 1, 0)});
    }
    std::vector<bvh::InstanceInput> instances{{0, worldTransform, gpu::MATERIAL_NONE},
                                              {1, glm::translate(glm::mat4(1.0f), offset + glm::vec3(0, 5, 0)), gpu::MATERIAL_NONE},
                                              {secondInstanceGroup, glm::translate(glm::mat4(1.0f), offset + glm::vec3(0, -5, 0)), gpu::MATERIAL_NONE}};
    return bvh::buildSceneBvh(groups, instances, {});
}

// The loose shapes' group is walked as part of the top level (traverse.glsl): instance 0's
// top-level leaf becomes its root node's entry, and FrameParams::world names its nodes and
// primitives. Only for an identity instance 0 whose group no other instance uses.
TEST(NodePacking, TheWorldGroupIsWalkedAsPartOfTheTopLevel) {
    const bvh::SceneBvh scene = worldAndPrototypeScene(glm::mat4(1.0f), 1);
    const InlinedWorld world = inlinedWorld(scene);
    ASSERT_TRUE(world.inlined);
    EXPECT_EQ(world.rootNode, scene.groups[0].rootNode);
    EXPECT_EQ(world.firstPrim, scene.groups[0].firstPrim);
    EXPECT_EQ(world.primCount, 30u);
    // The range holds exactly the nodes reachable from the group's root.
    std::vector<std::uint32_t> pending{world.rootNode};
    std::uint32_t reached = 0;
    while (!pending.empty()) {
        const std::uint32_t i = pending.back();
        pending.pop_back();
        ++reached;
        EXPECT_GE(i, world.firstNode);
        EXPECT_LT(i, world.firstNode + world.nodeCount);
        for (int k = 0; k < 2; ++k)
            if (bvh::childIsInner(scene.nodes[i], k)) pending.push_back(bvh::childLink(scene.nodes[i], k));
    }
    EXPECT_EQ(reached, world.nodeCount);

    const GpuNodes nodes = gpuNodes(scene);
    ASSERT_TRUE(nodes.packed);
    EXPECT_EQ(nodes.world, glm::uvec4(world.firstNode * gpu::GPU_NODE_TEXELS, world.nodeCount * gpu::GPU_NODE_TEXELS,
                                      world.firstPrim, world.primCount));
    // Among the top level's leaf entries: the world root's instead of instance 0's, and the others.
    int worldEntries = 0, instanceEntries = 0;
    for (std::uint32_t i = scene.topRoot; i < scene.nodes.size(); ++i) {
        gpu::GpuBvhNode packed;
        packed.xy0 = nodes.texels[3 * i];
        packed.xy1 = nodes.texels[3 * i + 1];
        packed.z01 = nodes.texels[3 * i + 2];
        for (int k = 0; k < 2; ++k) {
            if (bvh::childCount(scene.nodes[i], k) == 0) continue;
            const std::uint32_t entry = packedChildEntry(packed, k), instance = bvh::childLink(scene.nodes[i], k);
            if (instance == 0) {
                EXPECT_EQ(entry, world.rootNode * gpu::GPU_NODE_TEXELS);
                ++worldEntries;
            } else {
                EXPECT_EQ(entry, gpu::ENTRY_INSTANCE_BIT | instance);
                ++instanceEntries;
            }
        }
    }
    EXPECT_EQ(worldEntries, 1);
    EXPECT_EQ(instanceEntries, 2);

    // In the exact layout (geometry far from its origin) the entry and the range count 4 texels.
    const bvh::SceneBvh far = worldAndPrototypeScene(glm::mat4(1.0f), 1, glm::vec3(1e4f));
    const InlinedWorld farWorld = inlinedWorld(far);
    ASSERT_TRUE(farWorld.inlined);
    const GpuNodes exact = gpuNodes(far);
    ASSERT_FALSE(exact.packed);
    EXPECT_EQ(exact.world, glm::uvec4(farWorld.firstNode * gpu::GPU_EXACT_NODE_TEXELS, farWorld.nodeCount * gpu::GPU_EXACT_NODE_TEXELS,
                                      farWorld.firstPrim, farWorld.primCount));
    int exactWorldEntries = 0;
    for (std::uint32_t i = far.topRoot; i < far.nodes.size(); ++i)
        for (int k = 0; k < 2; ++k)
            if (bvh::childCount(far.nodes[i], k) != 0 && bvh::childLink(far.nodes[i], k) == 0) {
                EXPECT_EQ(exact.texels[gpu::GPU_EXACT_NODE_TEXELS * i + 3][k], farWorld.rootNode * gpu::GPU_EXACT_NODE_TEXELS);
                ++exactWorldEntries;
            }
    EXPECT_EQ(exactWorldEntries, 1);

    // Not inlined: a transformed instance 0, or a world group another instance also places.
    EXPECT_FALSE(inlinedWorld(worldAndPrototypeScene(glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0)), 1)).inlined);
    const bvh::SceneBvh shared = worldAndPrototypeScene(glm::mat4(1.0f), 0);
    EXPECT_FALSE(inlinedWorld(shared).inlined);
    EXPECT_EQ(gpuNodes(shared).world, glm::uvec4(0u));
}

}  // namespace
}  // namespace vkrt
