// buildSceneBvh: bottom levels (one per group), then the top level over the instances, flattened
// into one node array, with stats.
#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <new>
#include <span>
#include <stdexcept>
#include <string>

#include "bvh.h"
#include "flatten.h"
#include "instance_motion.h"
#include "prefault.h"
#include "primitives.h"
#include "sah_builder.h"
#include "top_level.h"
#include "wide_collapse.h"

namespace vkrt::bvh {

namespace {

// Groups at least this large (or holding more than half of the scene's primitives) are built one
// after another with the whole pool; smaller ones are built side by side, one thread each. Either
// way a group's tree is the same: buildSah's result does not depend on the pool.
constexpr std::size_t kLargeGroup = 32 * 1024;
// References are made in chunks of this many primitives (bounds + validation in parallel).
constexpr std::size_t kRefChunk = 4 * 1024;
// References ahead whose input primitive is prefetched while the records are written in leaf
// order (16 measured best of 0, 8, 16 and 48: commit 3637d13, docs/lab/2026-12-02-bvh-build.md).
constexpr std::uint32_t kEncodePrefetch = 16;
// No tree can be deeper than the CPU traversal's stack (traverse.cpp).
constexpr int kMaxTreeDepth = 64;

struct GroupBuild {
    HugeArray<PrimRef> refs;  // uninitialised until written: no pass just to zero it
    std::size_t count = 0;
    BuildTree tree;
    Aabb bounds;
};

void validateOptions(const BuildOptions& o) {
    if (o.maxBottomDepth < 1 || o.maxBottomDepth > kMaxTreeDepth)
        throw std::invalid_argument("bvh: maxBottomDepth must be in [1, " + std::to_string(kMaxTreeDepth) + "], got " +
                                    std::to_string(o.maxBottomDepth));
}

// Builds the PrimRefs of one group (validating every primitive) and its SAH tree, and writes the
// group's primitive records in leaf order into records[first...] / sources[first...] as each
// subtree completes. `alongside`, if given, runs on one thread of the pool while the others start
// on the references (see buildSceneBvh); records are written only after it has returned.
void buildGroup(const std::vector<PrimitiveInput>& prims, std::size_t groupIndex, const SahParams& params,
                ThreadPool& pool, gpu::Primitive* records, std::uint32_t* sources,
                const std::function<void()>& alongside, GroupBuild& out) {
    out.count = prims.size();
    out.refs = HugeArray<PrimRef>(out.count);
    const std::size_t chunks = (prims.size() + kRefChunk - 1) / kRefChunk;
    const std::size_t first = alongside ? 1 : 0;
    std::vector<Aabb> partial(chunks);
    pool.parallelFor(first + chunks, [&](std::size_t item) {
        if (item < first) {
            alongside();
            return;
        }
        const std::size_t c = item - first;
        const std::size_t end = std::min(prims.size(), (c + 1) * kRefChunk);
        // A local box: partial[c] in memory was reloaded on every primitive right after its stores
        // (the compiler cannot tell it from out.refs), a store-forwarding chain (commit 64cef83,
        // docs/lab/2026-12-02-bvh-build.md).
        // Grown as Aabb::grow does (new operand first), so the group's bounds keep their bits.
        Box4 box;
        for (std::size_t i = c * kRefChunk; i < end; ++i) {
            PrimRef r;
            if (!triangleRef(prims[i], static_cast<std::uint32_t>(i), r)) {
                validate(prims[i], groupIndex, i);
                r = PrimRef::make(boundsOf(prims[i]), static_cast<std::uint32_t>(i));
            }
            box.lo = _mm_min_ps(r.lo, box.lo);
            box.hi = _mm_max_ps(r.hi, box.hi);
            out.refs[i] = r;
        }
        partial[c] = box.toAabb();
    });
    for (const Aabb& b : partial) out.bounds.grow(b);
    const PrimRef* refs = out.refs.get();
    out.tree = buildSah(std::span<PrimRef>(out.refs.get(), out.count), params, pool,
                        [&](std::uint32_t begin, std::uint32_t end) {
                            for (std::uint32_t i = begin; i < end; ++i) {
                                // Leaf order scatters the reads of the input: fetch ahead.
                                if (i + kEncodePrefetch < end)
                                    _mm_prefetch(reinterpret_cast<const char*>(&prims[refs[i + kEncodePrefetch].id()]),
                                                 _MM_HINT_T0);
                                const std::uint32_t source = refs[i].id();
                                // Constructed in place (guaranteed elision), so encode writes the
                                // record itself: `records[i] = encode(...)` went through a stack
                                // temporary written in pieces and read back 32 bytes at a time,
                                // which cannot be store-forwarded (commit 64cef83); what is left
                                // of the record writing's time is reading the input.
                                ::new (static_cast<void*>(records + i)) gpu::Primitive(encode(prims[source]));
                                sources[i] = source;
                            }
                        });
}

// The CPU's 8-wide copy (SceneBvh::cpu): every tree counted first, then one allocation, then
// written. groupBlocks / topBlocks: the roots of the subtrees flattened in parallel.
void buildWideCopy(const std::vector<std::vector<std::uint32_t>>& groupBlocks, const std::vector<std::uint32_t>& topBlocks,
                   const std::vector<InstanceInput>& instances, ThreadPool& pool, SceneBvh& bvh) {
    std::vector<CollapsePlan> plans;
    for (std::size_t g = 0; g < groupBlocks.size(); ++g)
        plans.push_back(planCollapse(bvh.nodes, bvh.groups[g].rootNode, groupBlocks[g], pool));
    plans.push_back(planCollapse(bvh.nodes, bvh.topRoot, topBlocks, pool));
    std::size_t wideTotal = 0;
    for (const CollapsePlan& plan : plans) wideTotal += plan.total;
    reserveHuge(bvh.cpu.nodes, wideTotal);
    bvh.cpu.nodes.resize(wideTotal);
    std::uint32_t wideFirst = 0, bottomNodes = 0;
    for (std::size_t k = 0; k < plans.size(); ++k) {
        const std::uint32_t root = writeCollapse(bvh.nodes, plans[k], pool, bvh.cpu.nodes.data(), wideFirst);
        if (k < groupBlocks.size()) bvh.cpu.groupRoots.push_back(root);
        else bvh.cpu.topRoot = root;
        wideFirst += plans[k].total;
        if (k < groupBlocks.size()) bottomNodes = wideFirst;
    }
    bvh.cpu.triangles = buildTriangleGroups(bvh.prims, bvh.cpu.nodes.data(), bottomNodes, pool);
    for (const InstanceInput& in : instances)
        bvh.cpu.identity.push_back(in.objectToWorld == glm::mat4(1.0f) && !in.moving ? 1 : 0);
    bvh.cpu.built = true;
}

}  // namespace

SceneBvh buildSceneBvh(const std::vector<std::vector<PrimitiveInput>>& groups,
                       const std::vector<InstanceInput>& instances, const BuildOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    validateOptions(options);
    for (std::size_t i = 0; i < instances.size(); ++i)
        if (instances[i].group >= groups.size())
            throw std::invalid_argument("bvh: instance " + std::to_string(i) + " refers to group " +
                                        std::to_string(instances[i].group) + ", but there are only " +
                                        std::to_string(groups.size()) + " groups");
    std::size_t totalPrims = 0;
    for (const auto& g : groups) totalPrims += g.size();
    if (totalPrims >= NODE_NONE)
        throw std::invalid_argument("bvh: " + std::to_string(totalPrims) + " primitives exceed the 32-bit index range");

    const SahParams params{options.bins, options.maxLeafSize, options.traversalCost, options.intersectionCost,
                           options.maxBottomDepth};
    ThreadPool pool(options.threads);

    SceneBvh bvh;
    reserveHuge(bvh.prims, totalPrims);
    reserveHuge(bvh.primSource, totalPrims);
    prefaultCapacity(bvh.prims, totalPrims, pool);
    prefaultCapacity(bvh.primSource, totalPrims, pool);
    // The resizes value-initialise (a memset on one thread while the others waited). They run
    // alongside the first pool-wide group's reference pass instead, on whichever thread claims
    // them first (commit b88cf53, docs/lab/2026-12-02-bvh-build.md).
    bool resized = false;
    auto resize = [&] {
        bvh.prims.resize(totalPrims);
        bvh.primSource.resize(totalPrims);
        resized = true;
    };
    std::vector<std::uint32_t> firstPrims(groups.size());
    for (std::size_t g = 1; g < groups.size(); ++g)
        firstPrims[g] = firstPrims[g - 1] + static_cast<std::uint32_t>(groups[g - 1].size());

    // Bottom levels: large groups use the whole pool, small ones run side by side.
    std::vector<GroupBuild> built(groups.size());
    std::vector<std::size_t> small;
    auto build = [&](std::size_t g, ThreadPool& p, const std::function<void()>& alongside) {
        // The capacity is reserved: data() is the same before and after the resize.
        buildGroup(groups[g], g, params, p, bvh.prims.data() + firstPrims[g], bvh.primSource.data() + firstPrims[g],
                   alongside, built[g]);
    };
    for (std::size_t g = 0; g < groups.size(); ++g) {
        // A group holding most of the scene would leave the other threads idle side by side.
        if (groups[g].size() >= kLargeGroup || 2 * groups[g].size() > totalPrims) {
            if (resized) build(g, pool, {});
            else build(g, pool, resize);
        } else {
            small.push_back(g);
        }
    }
    if (!resized) resize();
    pool.parallelFor(small.size(), [&](std::size_t k) {
        ThreadPool local(1);
        build(small[k], local, {});
    });

    // Flatten in group order, so the layout does not depend on which thread built what.
    // A tree over n references has at most n - 1 inner nodes; every group and the top level
    // have at least one node.
    reserveHuge(bvh.nodes, totalPrims + 2 * groups.size() + instances.size() + 1);
    bvh.groups.resize(groups.size());
    // Per group: the blocks flattened in parallel, collapsed in parallel below.
    std::vector<std::vector<std::uint32_t>> groupBlocks(groups.size());
    std::uint32_t firstPrim = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        GroupBuild& b = built[g];
        GroupRange& range = bvh.groups[g];
        range.firstPrim = firstPrim;
        range.primCount = static_cast<std::uint32_t>(groups[g].size());
        range.lo = b.bounds.lo;
        range.hi = b.bounds.hi;
        const FlattenResult flat =
            flatten(b.tree, [&](const BuildNode& leaf) { return firstPrim + leaf.first(); }, params, pool, bvh.nodes);
        range.rootNode = flat.root;
        bvh.stats.leafCount += flat.leafCount;
        bvh.stats.bottomDepth = std::max(bvh.stats.bottomDepth, flat.depth);
        bvh.stats.sahCost += flat.sahCost;
        groupBlocks[g] = flat.blockRoots;
        firstPrim += range.primCount;
        b = GroupBuild{};  // release the references early
    }

    // Top level.
    std::vector<Aabb> worldBoxes(instances.size());
    bvh.instances.resize(instances.size());
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const GroupRange& g = bvh.groups[instances[i].group];
        bvh.instances[i] = makeInstance(instances[i], g.rootNode, i);
        if (instances[i].moving) {
            try {
                bvh.motions.push_back(decomposeMotion(instances[i].objectToWorld, instances[i].objectToWorldEnd));
            } catch (const std::invalid_argument& e) {
                throw std::invalid_argument("bvh: instance " + std::to_string(i) + ": " + e.what());
            }
            // The records follow the instances in the kernels' table.
            bvh.instances[i].info.w = static_cast<std::uint32_t>(instances.size() * gpu::INSTANCE_TEXELS +
                                                                 (bvh.motions.size() - 1) * gpu::MOTION_TEXELS);
            worldBoxes[i] = motionBounds(Aabb{g.lo, g.hi}, bvh.motions.back());
        } else {
            worldBoxes[i] = worldBounds(Aabb{g.lo, g.hi}, instances[i].objectToWorld);
        }
    }
    // The top level may use what the bottom levels leave of the kernels' stack: a kernel needs
    // topDepth + bottomDepth entries (one per inner node on the path in each level; nothing is
    // pushed to leave an instance: host/gpu/traversal_stack.h), at most TRAVERSAL_STACK_SIZE;
    // but never less than a balanced tree over the instances needs.
    int balancedDepth = 1;
    while ((std::size_t{1} << balancedDepth) < instances.size()) ++balancedDepth;
    SahParams topParams = params;
    topParams.maxDepth = std::min(kMaxTreeDepth, std::max(balancedDepth,
        static_cast<int>(gpu::TRAVERSAL_STACK_SIZE) - bvh.stats.bottomDepth));
    const FlattenResult top = buildTopLevel(worldBoxes, topParams, pool, bvh.nodes);
    bvh.topRoot = top.root;
    bvh.stats.topDepth = top.depth;
    bvh.stats.leafCount += top.leafCount;

    if (options.cpuTraversal) {
        const auto copyStart = std::chrono::steady_clock::now();
        buildWideCopy(groupBlocks, top.blockRoots, instances, pool, bvh);
        bvh.stats.cpuCopySeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - copyStart).count();
    }
    bvh.stats.nodeCount = bvh.nodes.size();
    bvh.stats.bytes = bvh.nodes.size() * sizeof(BinaryNode) + bvh.prims.size() * sizeof(gpu::Primitive) +
                      bvh.instances.size() * sizeof(gpu::Instance);
    bvh.stats.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return bvh;
}

}  // namespace vkrt::bvh
