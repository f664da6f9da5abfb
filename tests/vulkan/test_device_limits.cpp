// Device limits: each limit refuses one byte (or texel) over it and accepts exactly its size,
// with an error naming the limit, the buffer and both sizes; the caps for tests; and the
// renderer refusing a scene before allocating anything. Also the BVH traversal stack bound.
#include <cstdlib>
#include <stdexcept>

#include <gtest/gtest.h>

#include "device_limits.h"
#include "scene_upload.h"
#include "traversal_stack.h"
#include "vulkan_errors.h"
#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::VulkanTest;

BufferLimits someLimits() {
    BufferLimits l;
    l.maxStorageBufferRange = 1000;
    l.maxTexelBufferElements = 50;  // texels of 16 bytes: 800 bytes
    l.maxUniformBufferRange = 300;
    l.maxMemoryAllocationSize = 2000;
    l.heapBytes = 5000;
    return l;
}

std::string refusal(const BufferLimits& limits, BufferKind kind, std::uint64_t bytes) {
    try {
        checkBufferFits(limits, "test buffer", kind, bytes);
    } catch (const DeviceLimitExceeded& e) {
        return e.what();
    }
    return "";
}

TEST(DeviceLimits, StorageBufferRangeBothSides) {
    EXPECT_NO_THROW(checkBufferFits(someLimits(), "b", BufferKind::Storage, 1000));
    const std::string message = refusal(someLimits(), BufferKind::Storage, 1001);
    EXPECT_NE(message.find("maxStorageBufferRange"), std::string::npos) << message;
    EXPECT_NE(message.find("'test buffer'"), std::string::npos) << message;
    EXPECT_NE(message.find("1001 bytes"), std::string::npos) << message;
    EXPECT_NE(message.find("1000 bytes"), std::string::npos) << message;
}

TEST(DeviceLimits, TexelBufferElementsBothSides) {
    EXPECT_NO_THROW(checkBufferFits(someLimits(), "b", BufferKind::StorageTexel, 50 * 16));
    const std::string message = refusal(someLimits(), BufferKind::StorageTexel, 50 * 16 + 1);  // 51 texels
    EXPECT_NE(message.find("maxTexelBufferElements"), std::string::npos) << message;
    EXPECT_NE(message.find("51 texels"), std::string::npos) << message;
    EXPECT_NE(message.find("50 texels"), std::string::npos) << message;
}

TEST(DeviceLimits, UniformBufferRangeBothSides) {
    EXPECT_NO_THROW(checkBufferFits(someLimits(), "b", BufferKind::Uniform, 300));
    EXPECT_NE(refusal(someLimits(), BufferKind::Uniform, 301).find("maxUniformBufferRange"), std::string::npos);
}

TEST(DeviceLimits, AllocationSizeBothSides) {
    BufferLimits l = someLimits();
    l.maxStorageBufferRange = 10000;  // so the allocation limit is the one that bites
    EXPECT_NO_THROW(checkBufferFits(l, "b", BufferKind::Storage, 2000));
    EXPECT_NE(refusal(l, BufferKind::Storage, 2001).find("maxMemoryAllocationSize"), std::string::npos);
    EXPECT_NE(refusal(l, BufferKind::Plain, 2001).find("maxMemoryAllocationSize"), std::string::npos);
}

TEST(DeviceLimits, HeapBothSides) {
    EXPECT_NO_THROW(checkTotalFits(someLimits(), 5000));
    try {
        checkTotalFits(someLimits(), 5001);
        FAIL() << "5001 bytes accepted in a 5000-byte heap";
    } catch (const DeviceLimitExceeded& e) {
        EXPECT_NE(std::string(e.what()).find("heap"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("5001 bytes"), std::string::npos) << e.what();
    }
}

TEST(DeviceLimits, CapLowersEveryPerBufferLimitButNotTheHeap) {
    const BufferLimits capped = capLimits(someLimits(), 160, "limited for testing");
    EXPECT_EQ(capped.maxStorageBufferRange, 160u);
    EXPECT_EQ(capped.maxTexelBufferElements, 10u);
    EXPECT_EQ(capped.maxUniformBufferRange, 160u);
    EXPECT_EQ(capped.maxMemoryAllocationSize, 160u);
    EXPECT_EQ(capped.heapBytes, 5000u);
    EXPECT_NE(refusal(capped, BufferKind::Storage, 161).find("limited for testing"), std::string::npos);
    EXPECT_EQ(capLimits(someLimits(), 1u << 30, "").maxStorageBufferRange, 1000u);  // never raises a limit
}

TEST(DeviceLimits, EnvironmentOverride) {
    ::unsetenv("VKRT_MAX_BUFFER_BYTES");
    EXPECT_EQ(maxBufferBytesFromEnvironment(), std::nullopt);
    ::setenv("VKRT_MAX_BUFFER_BYTES", "4096", 1);
    EXPECT_EQ(maxBufferBytesFromEnvironment(), 4096u);
    for (const char* bad : {"12k", "-5", "0", "lots"}) {
        ::setenv("VKRT_MAX_BUFFER_BYTES", bad, 1);
        EXPECT_THROW(maxBufferBytesFromEnvironment(), std::invalid_argument) << bad;
    }
    ::unsetenv("VKRT_MAX_BUFFER_BYTES");
}

TEST_F(VulkanTest, EnvironmentOverrideReachesTheContext) {
    ::setenv("VKRT_MAX_BUFFER_BYTES", "4096", 1);
    const Context& c = context();
    ::unsetenv("VKRT_MAX_BUFFER_BYTES");
    EXPECT_EQ(c.limits().maxStorageBufferRange, 4096u);
    EXPECT_EQ(c.limits().maxTexelBufferElements, 256u);
    EXPECT_NE(c.limits().capNote.find("VKRT_MAX_BUFFER_BYTES"), std::string::npos);
}

// The accumulation buffer (a texel buffer of 16 bytes per pixel, padded by stableTexelBufferBytes)
// is the largest buffer of a tiny scene: a cap of exactly its 64x64 size lets 64x64 through and
// refuses 64x65, naming the buffer, the limit and both sizes.
TEST_F(VulkanTest, RendererAcceptsASceneAtTheLimitAndRefusesOneOver) {
    test::TinyScene tiny;
    const std::uint64_t fits = stableTexelBufferBytes(64 * 64 * 16);
    const std::uint64_t over = stableTexelBufferBytes(64 * 65 * 16);
    ASSERT_GT(over, fits);
    GpuRenderer& gpu = renderer({}, {.kernelSpirv = test::testKernel("camera_rays"), .maxBufferBytes = fits});
    EXPECT_NO_THROW(gpu.render(tiny.gpu(), test::smallRender(64, 64, 1)));
    try {
        gpu.render(tiny.gpu(), test::smallRender(64, 65, 1));
        FAIL() << "a " << over << "-byte accumulation buffer passed a " << fits << "-byte limit";
    } catch (const DeviceLimitExceeded& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("accumulation"), std::string::npos) << m;
        EXPECT_NE(m.find("maxTexelBufferElements"), std::string::npos) << m;
        EXPECT_NE(m.find(std::to_string(over / 16) + " texels"), std::string::npos) << m;
        EXPECT_NE(m.find(std::to_string(fits / 16) + " texels"), std::string::npos) << m;
    }
}

TEST(SceneBuffers, PlanPadsEmptyTablesToOneElement) {
    test::TinyScene tiny;
    SceneTables tables;  // all empty
    const GpuNodes nodes = gpuNodes(tiny.accel.bvh);
    const std::vector<BufferPlan> plan = planSceneBuffers(tables, tiny.accel.bvh, nodeBytes(nodes), 10);
    ASSERT_EQ(plan.size(), gpu::RENDER_BINDING_COUNT);
    // One zeroed element, then the texel-buffer padding that keeps lavapipe's JIT key stable.
    EXPECT_EQ(plan[gpu::BINDING_SHADERS].bytes, stableTexelBufferBytes(sizeof(gpu::Material)));
    EXPECT_EQ(plan[gpu::BINDING_SHADERS].kind, BufferKind::StorageTexel);
    EXPECT_EQ(plan[gpu::BINDING_TEXELS].bytes, stableTexelBufferBytes(4));
    EXPECT_EQ(plan[gpu::BINDING_TEXELS].texelBytes, 4u);
    EXPECT_EQ(plan[gpu::BINDING_NODES].bytes, stableTexelBufferBytes(2 * sizeof(gpu::GpuBvhNode)));  // two packed nodes
    EXPECT_TRUE(nodes.packed);
    EXPECT_EQ(plan[gpu::BINDING_NODES].kind, BufferKind::StorageTexel);
    EXPECT_EQ(plan[gpu::BINDING_ACCUM].bytes, stableTexelBufferBytes(10 * 16));
    EXPECT_EQ(plan[gpu::BINDING_ACCUM].kind, BufferKind::StorageTexel);
    EXPECT_EQ(plan[gpu::BINDING_FRAME].kind, BufferKind::Uniform);
}

TEST(SceneBuffers, TexelBufferSizesAvoidLavapipesRecompileTriggers) {
    for (std::uint64_t bytes : {16ull, 64ull, 128ull, 4096ull, 48ull * 1000, 65536ull, 65536ull * 3 + 16, 1ull << 27}) {
        const std::uint64_t padded = stableTexelBufferBytes(bytes);
        EXPECT_GE(padded, bytes);
        EXPECT_LE(padded, bytes + 16 + 256);
        EXPECT_EQ(padded % 16, 0u);
        EXPECT_NE(padded & (padded - 1), 0u) << padded << " is a power of two";
        EXPECT_NE((padded >> 8) & 0xff, 0u) << padded;
    }
    EXPECT_EQ(stableTexelBufferBytes(48 * 1000), 48u * 1000);  // already stable: unchanged
}

// A chain of `depth` inner nodes: node i has child 0 = node i+1 (inner) and child 1 = a leaf; the
// last node has two leaves.
std::vector<bvh::BinaryNode> chain(std::uint32_t first, std::uint32_t depth) {
    std::vector<bvh::BinaryNode> nodes(depth);
    for (std::uint32_t i = 0; i < depth; ++i) {
        const bool last = i + 1 == depth;
        nodes[i].link = last ? glm::uvec4(0u, 0u, 1u, 1u) : glm::uvec4(first + i + 1, 0u, 0u, 1u);
    }
    return nodes;
}

TEST(TraversalStack, DepthOfAChain) {
    EXPECT_EQ(innerDepth(chain(0, 1), 0), 1u);
    EXPECT_EQ(innerDepth(chain(0, 30), 0), 30u);
    EXPECT_EQ(innerDepth(chain(0, 30), 29), 1u);
}

TEST(TraversalStack, BothSidesOfTheKernelsStack) {
    bvh::SceneBvh b;
    b.nodes = chain(0, gpu::TRAVERSAL_STACK_SIZE);
    b.instances.resize(1);
    b.instances[0].info.x = 0;
    EXPECT_EQ(traversalStackNeed(b, false), gpu::TRAVERSAL_STACK_SIZE);
    EXPECT_NO_THROW(checkTraversalStack(b, false));
    b.nodes = chain(0, gpu::TRAVERSAL_STACK_SIZE + 1);
    try {
        checkTraversalStack(b, false);
        FAIL() << "a BVH deeper than the stack was accepted";
    } catch (const DeviceLimitExceeded& e) {
        EXPECT_NE(std::string(e.what()).find(std::to_string(gpu::TRAVERSAL_STACK_SIZE + 1) + " entries"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("TRAVERSAL_STACK_SIZE is " + std::to_string(gpu::TRAVERSAL_STACK_SIZE)), std::string::npos);
    }
}

// No marker for the way back from an instance (traverse.glsl: each node is tested with its level's
// ray), so the need is the two levels' depths added.
TEST(TraversalStack, InstancingAddsTheTopLevel) {
    bvh::SceneBvh b;
    b.nodes = chain(0, 10);                       // bottom level, depth 10
    const auto top = chain(10, 3);                // top level, depth 3
    b.nodes.insert(b.nodes.end(), top.begin(), top.end());
    b.topRoot = 10;
    b.instances.resize(2);
    b.instances[0].info.x = 5;                    // depth 5
    b.instances[1].info.x = 0;                    // depth 10
    EXPECT_EQ(traversalStackNeed(b, true), 3u + 10u);
    EXPECT_EQ(traversalStackNeed(b, false), 5u);  // instance 0 only
    EXPECT_THROW(checkTraversalStack(b, true, 12), DeviceLimitExceeded);
    EXPECT_NO_THROW(checkTraversalStack(b, true, 13));
}

TEST(TraversalStack, LeavesMustFitOneStackEntry) {
    bvh::SceneBvh b;
    b.nodes = chain(0, 3);  // the last node's children are leaves of one primitive each
    b.instances.resize(1);
    b.instances[0].info.x = 0;
    // The top level: one node whose only child is instance 0.
    bvh::BinaryNode top = b.nodes[2];
    top.link = glm::uvec4(0u, bvh::NODE_NONE, 1u, 0u);
    b.nodes.push_back(top);
    b.topRoot = 3;
    b.nodes[2].link = glm::uvec4(gpu::LEAF_ENTRY_MAX_FIRST, 0u, gpu::LEAF_ENTRY_MAX_COUNT, 1u);
    EXPECT_NO_THROW(checkTraversalStack(b, false));
    b.nodes[2].link.z = gpu::LEAF_ENTRY_MAX_COUNT + 1;
    try {
        checkTraversalStack(b, false);
        FAIL() << "a leaf of " << gpu::LEAF_ENTRY_MAX_COUNT + 1 << " primitives was accepted";
    } catch (const DeviceLimitExceeded& e) {
        EXPECT_NE(std::string(e.what()).find("leaf of 16 primitives"), std::string::npos) << e.what();
    }
    b.nodes[2].link = glm::uvec4(gpu::LEAF_ENTRY_MAX_FIRST + 1, 0u, 1u, 1u);
    EXPECT_THROW(checkTraversalStack(b, false), DeviceLimitExceeded);
    // Top-level leaves are pushed as instance entries: their counts are not packed.
    b.nodes[2].link = glm::uvec4(0u, 0u, 1u, 1u);
    b.nodes[3].link = glm::uvec4(0u, bvh::NODE_NONE, gpu::LEAF_ENTRY_MAX_COUNT + 5, 0u);
    EXPECT_NO_THROW(checkTraversalStack(b, true));
}

TEST(TraversalStack, CyclesAndBadLinksAreRefused) {
    std::vector<bvh::BinaryNode> nodes = chain(0, 2);
    nodes[1].link = glm::uvec4(0u, 0u, 0u, 1u);  // back to the root
    EXPECT_THROW(innerDepth(nodes, 0), std::logic_error);
    nodes[1].link = glm::uvec4(9u, 0u, 0u, 1u);  // past the end
    EXPECT_THROW(innerDepth(nodes, 0), std::logic_error);
}

}  // namespace
}  // namespace vkrt
