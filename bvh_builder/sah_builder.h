// Binned SAH builder: a binary tree over primitive references, before any GPU layout is chosen
// (flatten.h does that). Where a node is split, and when it stays a leaf: sah_split.h. Here:
//  - When the centroids cannot be binned (all identical), or the SAH split would let the tree grow
//    deeper than maxDepth, the node is split at the median along its widest centroid axis (by count
//    when every centroid is identical), so the build always terminates and the depth stays bounded.
//  - Children are built in parallel as independent subtrees; the tree is identical for any number
//    of threads because every step (min/max binning, in-place partition) is order-independent or
//    runs on one thread per subtree.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "aabb.h"
#include "huge_pages.h"
#include "sah_split.h"
#include "thread_pool.h"

namespace vkrt::bvh {

// A leaf over refs[first, first + count), or an inner node with two children. 32 bytes, and no
// member initialisers: the node array is allocated uninitialised (only used slots are written).
struct BuildNode {
    static constexpr std::uint32_t kLeafBit = 0x80000000u;

    glm::vec3 lo, hi;
    std::uint32_t a;  // inner: left child; leaf: first reference
    std::uint32_t b;  // inner: right child; leaf: kLeafBit | count

    static BuildNode innerNode(const Aabb& box, std::uint32_t left, std::uint32_t right) {
        return {box.lo, box.hi, left, right};
    }
    Aabb box() const { return {lo, hi}; }
    bool leaf() const { return (b & kLeafBit) != 0; }
    std::uint32_t first() const { return a; }
    std::uint32_t count() const { return leaf() ? b & ~kLeafBit : 0; }
    std::uint32_t left() const { return a; }
    std::uint32_t right() const { return b; }
};
static_assert(sizeof(BuildNode) == 32);

// The nodes of a tree, reachable from root. Subtrees built in parallel each own a slice of the
// array sized for the worst case (2n - 1 nodes for n references), so some slots stay unused.
struct BuildTree {
    HugeArray<BuildNode> nodes;  // empty when there were no primitives
    std::uint32_t root = 0;
    // Nodes [0, topCount) were made by the top phase; every other node belongs to exactly one of
    // the subtrees rooted at subtreeRoots (built as separate jobs, in this order), which later
    // passes can also process in parallel.
    std::uint32_t topCount = 0;
    std::vector<std::uint32_t> subtreeRoots;
    std::vector<std::uint32_t> subtreeInnerNodes;  // inner nodes of each of those subtrees

    bool empty() const { return !nodes; }
    const BuildNode& operator[](std::uint32_t i) const { return nodes[i]; }
};

// Reorders refs so that every leaf's references are contiguous, in depth-first order of the tree.
// subtreeDone(begin, end), if given, runs on the building thread as soon as refs[begin, end) have
// reached their final order (once per subtree job; the jobs cover refs exactly once), so callers
// can consume them while they are still in cache.
using SubtreeDone = std::function<void(std::uint32_t begin, std::uint32_t end)>;
BuildTree buildSah(std::span<PrimRef> refs, const SahParams& params, ThreadPool& pool,
                   const SubtreeDone& subtreeDone = {});


}  // namespace vkrt::bvh
