#include "node_packing.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "node_layout.h"
#include "top_level.h"

namespace vkrt {

namespace {

constexpr std::uint32_t kSignBit = 0x80000000u;
constexpr std::uint32_t kInfinityBits = 0x7f800000u;

std::uint32_t lowBits(std::uint32_t value, unsigned bits) { return value & ((1u << bits) - 1u); }

}  // namespace

std::uint32_t roundDownWithLowBits(float value, std::uint32_t payload, unsigned bits) {
    if (!std::isfinite(value)) throw std::invalid_argument("a BVH box bound is not finite");
    const std::uint32_t step = 1u << bits;
    const std::uint32_t b = std::bit_cast<std::uint32_t>(value);
    const std::uint32_t magnitude = b & ~kSignBit;
    // Candidates with the payload come every `step` patterns. Among floats of one sign the bit
    // pattern orders the magnitude, so: positive values go down by lowering the pattern,
    // negative ones by raising it.
    std::uint32_t candidate = (magnitude & ~(step - 1u)) | payload;
    if ((b & kSignBit) == 0u) {
        if (candidate <= magnitude) return candidate;
        if (magnitude >= step) return candidate - step;
        return kSignBit | payload;  // below +0 with that payload: the tiny negative one (<= 0 <= value)
    }
    if (candidate < magnitude) candidate += step;
    if (candidate >= kInfinityBits)
        throw std::invalid_argument("a BVH box bound (" + std::to_string(value) +
                                    ") is too close to the largest float to be rounded outward");
    return kSignBit | candidate;
}

std::uint32_t roundUpWithLowBits(float value, std::uint32_t payload, unsigned bits) {
    // Negation flips the sign bit only: the smallest float >= v is minus the largest <= -v.
    return roundDownWithLowBits(-value, payload, bits) ^ kSignBit;
}

namespace {

std::uint32_t nodeEntry(std::uint32_t index, std::uint32_t nodeTexels) {
    const std::uint64_t firstTexel = std::uint64_t{index} * nodeTexels;
    if (firstTexel >= gpu::ENTRY_LEAF_BIT)  // bits 30 and 31 mark leaves and instances
        throw std::logic_error("BVH node index " + std::to_string(index) + " does not fit a stack entry");
    return static_cast<std::uint32_t>(firstTexel);
}

}  // namespace

InlinedWorld inlinedWorld(const bvh::SceneBvh& bvh) {
    InlinedWorld world;
    if (bvh.instances.size() < 2 || !bvh::isIdentity(bvh.instances[0])) return world;
    const std::uint32_t group = gpu::instanceGroup(bvh.instances[0].info);
    for (std::size_t i = 1; i < bvh.instances.size(); ++i)
        if (gpu::instanceGroup(bvh.instances[i].info) == group) return world;
    if (group >= bvh.groups.size() || bvh.groups[group].primCount == 0) return world;
    const std::uint32_t root = bvh.groups[group].rootNode;
    if (root >= bvh.nodes.size() || root != gpu::instanceRootNode(bvh.instances[0].info)) return world;
    // The group's nodes, from its root: the kernel tells them by one index range.
    std::uint32_t lo = root, hi = root, count = 0;
    std::vector<std::uint32_t> pending{root};
    while (!pending.empty()) {
        const std::uint32_t i = pending.back();
        pending.pop_back();
        lo = std::min(lo, i);
        hi = std::max(hi, i);
        ++count;
        for (int k = 0; k < 2; ++k)
            if (bvh::childIsInner(bvh.nodes[i], k)) pending.push_back(bvh::childLink(bvh.nodes[i], k));
    }
    if (hi - lo + 1 != count || hi >= bvh.topRoot) return world;
    world.inlined = true;
    world.rootNode = root;
    world.firstNode = lo;
    world.nodeCount = count;
    world.firstPrim = bvh.groups[group].firstPrim;
    world.primCount = bvh.groups[group].primCount;
    return world;
}

glm::uvec4 inlinedWorldParams(const InlinedWorld& world, std::uint32_t nodeTexels) {
    if (!world.inlined) return glm::uvec4(0u);
    return {nodeEntry(world.firstNode, nodeTexels), world.nodeCount * nodeTexels, world.firstPrim, world.primCount};
}

std::uint32_t childStackEntry(const bvh::BinaryNode& node, int k, bool topLevel, std::uint32_t nodeTexels, const InlinedWorld& world) {
    const std::uint32_t link = bvh::childLink(node, k);
    const std::uint32_t count = bvh::childCount(node, k);
    if (count == 0) {
        if (link == bvh::NODE_NONE) return gpu::ENTRY_NONE;
        return nodeEntry(link, nodeTexels);
    }
    if (topLevel) {
        // A top-level leaf is one instance (bvh_builder/top_level.cpp builds them so).
        if (count != 1u || link >= gpu::ENTRY_NONE - gpu::ENTRY_INSTANCE_BIT - 1u)
            throw std::logic_error("top-level BVH leaf of " + std::to_string(count) + " instances at " + std::to_string(link));
        if (world.inlined && link == 0u) return nodeEntry(world.rootNode, nodeTexels);
        return gpu::ENTRY_INSTANCE_BIT | link;
    }
    if (count > gpu::LEAF_ENTRY_MAX_COUNT || link > gpu::LEAF_ENTRY_MAX_FIRST)
        throw std::logic_error("BVH leaf of " + std::to_string(count) + " primitives at " + std::to_string(link) +
                               " does not fit a stack entry (checkLeafEntries lets none through)");
    return gpu::ENTRY_LEAF_BIT | (link << 4u) | count;
}

std::vector<bool> topLevelNodes(const bvh::SceneBvh& bvh) {
    std::vector<bool> topLevel(bvh.nodes.size(), false);
    std::vector<std::uint32_t> pending;
    if (bvh.topRoot < bvh.nodes.size()) pending.push_back(bvh.topRoot);
    while (!pending.empty()) {
        const std::uint32_t index = pending.back();
        pending.pop_back();
        if (index >= bvh.nodes.size()) throw std::logic_error("BVH node link " + std::to_string(index) + " is outside the nodes");
        if (topLevel[index]) throw std::logic_error("the top-level BVH's node links form a cycle");
        topLevel[index] = true;
        for (int k = 0; k < 2; ++k)
            if (bvh::childIsInner(bvh.nodes[index], k)) pending.push_back(bvh::childLink(bvh.nodes[index], k));
    }
    return topLevel;
}

void checkTopLevelLast(const bvh::SceneBvh& bvh) {
    const std::vector<bool> topLevel = topLevelNodes(bvh);
    for (std::size_t i = 0; i < topLevel.size(); ++i)
        if (topLevel[i] != (i >= bvh.topRoot))
            throw std::logic_error("BVH node " + std::to_string(i) + (topLevel[i] ? " is top-level but precedes" : " is bottom-level but follows") +
                                   " the top-level root " + std::to_string(bvh.topRoot) +
                                   ": the kernel needs the top level last (traverse.glsl, topLevelNode)");
}

std::vector<gpu::GpuBvhNode> packNodes(const bvh::SceneBvh& bvh, const InlinedWorld& world) {
    const std::vector<bool> topLevel = topLevelNodes(bvh);
    constexpr unsigned xyBits = gpu::NODE_ENTRY_XY_BITS, zBits = gpu::NODE_ENTRY_Z_BITS;
    std::vector<gpu::GpuBvhNode> packed(bvh.nodes.size());
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const bvh::BinaryNode& node = bvh.nodes[i];
        gpu::GpuBvhNode& out = packed[i];
        for (int k = 0; k < 2; ++k) {
            const std::uint32_t entry = childStackEntry(node, k, topLevel[i], gpu::GPU_NODE_TEXELS, world);
            const glm::uvec4& xy = k == 0 ? node.xy0 : node.xy1;
            glm::uvec4& packedXy = k == 0 ? out.xy0 : out.xy1;
            // lo.x hi.x lo.y hi.y carry entry bits 0-23, lo.z and hi.z bits 24-31.
            for (int c = 0; c < 4; ++c) {
                const float bound = std::bit_cast<float>(xy[c]);
                const std::uint32_t payload = lowBits(entry >> (xyBits * c), xyBits);
                packedXy[c] = c % 2 == 0 ? roundDownWithLowBits(bound, payload, xyBits) : roundUpWithLowBits(bound, payload, xyBits);
            }
            const float loZ = std::bit_cast<float>(node.z01[2 * k]), hiZ = std::bit_cast<float>(node.z01[2 * k + 1]);
            out.z01[2 * k] = roundDownWithLowBits(loZ, lowBits(entry >> (4 * xyBits), zBits), zBits);
            out.z01[2 * k + 1] = roundUpWithLowBits(hiZ, lowBits(entry >> (4 * xyBits + zBits), zBits), zBits);
        }
    }
    return packed;
}

namespace {

// The packed child boxes' total surface area over the builder's, in the tree under `root`.
double treeAreaGrowth(const bvh::SceneBvh& bvh, const std::vector<gpu::GpuBvhNode>& packed, std::uint32_t root) {
    double exactArea = 0.0, packedArea = 0.0;
    std::vector<std::uint32_t> pending;
    if (root < bvh.nodes.size()) pending.push_back(root);
    while (!pending.empty()) {
        const std::uint32_t i = pending.back();
        pending.pop_back();
        const bvh::BinaryNode& node = bvh.nodes[i];
        for (int k = 0; k < 2; ++k) {
            if (bvh::childCount(node, k) == 0 && bvh::childLink(node, k) == bvh::NODE_NONE) continue;  // empty slot
            if (bvh::childIsInner(node, k)) pending.push_back(bvh::childLink(node, k));
            exactArea += bvh::childBox(node, k).halfArea();
            packedArea += packedChildBox(packed[i], k).halfArea();
        }
    }
    if (exactArea > 0.0) return packedArea / exactArea;
    return packedArea > 0.0 ? INFINITY : 1.0;
}

}  // namespace

GpuNodes gpuNodes(const bvh::SceneBvh& bvh) {
    checkTopLevelLast(bvh);
    const InlinedWorld world = inlinedWorld(bvh);
    GpuNodes out;
    std::vector<gpu::GpuBvhNode> packed;
    try {
        packed = packNodes(bvh, world);
        // Per tree: a huge top-level box must not hide a mesh whose own boxes grew.
        out.areaGrowth = treeAreaGrowth(bvh, packed, bvh.topRoot);
        for (const bvh::GroupRange& group : bvh.groups)
            out.areaGrowth = std::max(out.areaGrowth, treeAreaGrowth(bvh, packed, group.rootNode));
    } catch (const std::invalid_argument&) {
        // A bound within 2^6 ulp of the largest float has no float outside it with the entry's
        // bits: such a scene keeps the exact layout rather than failing.
        out.areaGrowth = INFINITY;
    }
    out.packed = out.areaGrowth <= kMaxPackedAreaGrowth;
    out.world = inlinedWorldParams(world, out.packed ? gpu::GPU_NODE_TEXELS : gpu::GPU_EXACT_NODE_TEXELS);
    if (out.packed) {
        out.texels.reserve(packed.size() * gpu::GPU_NODE_TEXELS);
        for (const gpu::GpuBvhNode& n : packed) out.texels.insert(out.texels.end(), {n.xy0, n.xy1, n.z01});
        return out;
    }
    out.texels.reserve(bvh.nodes.size() * gpu::GPU_EXACT_NODE_TEXELS);
    for (std::size_t i = 0; i < bvh.nodes.size(); ++i) {
        const bvh::BinaryNode& n = bvh.nodes[i];
        const bool topLevel = i >= bvh.topRoot;  // checkTopLevelLast above: no second walk of the top level
        const glm::uvec4 entries(childStackEntry(n, 0, topLevel, gpu::GPU_EXACT_NODE_TEXELS, world),
                                 childStackEntry(n, 1, topLevel, gpu::GPU_EXACT_NODE_TEXELS, world), 0u, 0u);
        out.texels.insert(out.texels.end(), {n.xy0, n.xy1, n.z01, entries});
    }
    return out;
}

bvh::Aabb packedChildBox(const gpu::GpuBvhNode& node, int k) {
    const glm::uvec4& xy = k == 0 ? node.xy0 : node.xy1;
    auto f = [](std::uint32_t u) { return std::bit_cast<float>(u); };
    bvh::Aabb box;
    box.lo = {f(xy[0]), f(xy[2]), f(node.z01[2 * k])};
    box.hi = {f(xy[1]), f(xy[3]), f(node.z01[2 * k + 1])};
    return box;
}

std::uint32_t packedChildEntry(const gpu::GpuBvhNode& node, int k) {
    constexpr unsigned xyBits = gpu::NODE_ENTRY_XY_BITS, zBits = gpu::NODE_ENTRY_Z_BITS;
    const glm::uvec4& xy = k == 0 ? node.xy0 : node.xy1;
    std::uint32_t entry = 0;
    for (int c = 0; c < 4; ++c) entry |= lowBits(xy[c], xyBits) << (xyBits * c);
    entry |= lowBits(node.z01[2 * k], zBits) << (4 * xyBits);
    entry |= lowBits(node.z01[2 * k + 1], zBits) << (4 * xyBits + zBits);
    return entry;
}

}  // namespace vkrt
