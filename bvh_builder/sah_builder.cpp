#include "sah_builder.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>

namespace vkrt::bvh {

namespace {

// Above this many references a node's binning is spread over the pool, and its children are
// split further before being handed out as subtree jobs; below it one thread builds the subtree.
// 8K rather than 16K: a 16K-triangle mesh was a single job on one thread, and smaller jobs
// balance better at the end of larger builds (commit 0bdb3cf).
constexpr std::uint32_t kParallelNodeSize = 8 * 1024;
// References per binning chunk: large enough that merging bins is negligible, small enough that
// a range just above kParallelNodeSize is binned by 2 threads.
constexpr std::uint32_t kBinChunk = 4 * 1024;

// A range of references still to be turned into a subtree. Boxes: geometry, and twice the centroids.
struct Range {
    std::uint32_t begin = 0, end = 0;
    Box4 bounds, centroids;
    int level = 0;  // inner-node level this range's node would sit at (root = 1)
    std::uint32_t size() const { return end - begin; }
};

struct Bounds2 {
    Box4 bounds, centroids;
    void add(const PrimRef& r) {
        bounds.grow(r.lo, r.hi);
        centroids.growPoint(r.centroid2());
    }
};

struct Decision {
    enum Kind { Leaf, Median, Binned } kind = Leaf;
    int axis = 0, plane = 0;
};

// Smallest number of inner-node levels that can hold n references with median splits.
int levelsNeeded(std::uint32_t n, std::uint32_t maxLeaf) {
    int levels = 0;
    while (n > maxLeaf) {
        n = (n + 1) / 2;
        ++levels;
    }
    return levels;
}

// Node slots for one subtree job, taken in chunks from a cursor shared by all jobs, so the slots in
// use are packed at the front of the one node array. Each job's worst case is reserved (2m - 1
// nodes for m references) but typically half used; with a fixed slice per job every 2 MiB page
// of the array was touched (zeroed by the kernel when fresh) and half of it never used. A job never
// takes more than its worst case, so the array's size is unchanged; which slots a job gets depends
// on timing, but nothing downstream depends on build-node indices, only on the tree. It takes
// page zeroing out of the subtree jobs' profile (docs/lab/2026-12-02-bvh-build.md).
class NodeAllocator {
public:
    NodeAllocator(std::atomic<std::uint32_t>& cursor, std::uint32_t worstCase) : cursor_(cursor), budget_(worstCase) {}
    std::uint32_t take() {
        if (next_ == end_) {
            const std::uint32_t size = std::min(kChunk, budget_);
            next_ = cursor_.fetch_add(size, std::memory_order_relaxed);
            end_ = next_ + size;
            budget_ -= size;
        }
        ++taken_;
        return next_++;
    }
    std::uint32_t taken() const { return taken_; }

private:
    static constexpr std::uint32_t kChunk = 4096;  // 128 KiB of nodes
    std::atomic<std::uint32_t>& cursor_;
    std::uint32_t budget_, next_ = 0, end_ = 0, taken_ = 0;
};

class Builder {
public:
    Builder(std::span<PrimRef> refs, const SahParams& p, ThreadPool& pool, const SubtreeDone& done)
        : refs_(refs), p_(p), pool_(pool), done_(done) {}

    BuildTree run();

private:
    // Splits a range into two children, or returns false when it becomes a leaf.
    // branchFree: the partition subtree jobs use (see partitionByBin).
    bool split(const Range& r, bool branchFree, Range& left, Range& right);
    bool splitSmall(const Range& r, Range& left, Range& right);
    // For ranges above kSweepSize: what to do given the range's bins, and doing it.
    Decision decideLarge(const Range& r, const Bins& bins, const BinMapper& mapper) const;
    // bins: the range's bins if at hand (subtree jobs), for the children's boxes.
    void apply(const Range& r, const Decision& d, const BinMapper& mapper, bool branchFree, Range& left, Range& right,
               const Bins* bins = nullptr);
    void partitionByBin(const Range& r, const BinMapper::Axis& map, int plane, bool branchFree, const Bins* bins,
                        Range& left, Range& right);
    void splitMedian(const Range& r, Range& left, Range& right);
    void childRanges(const Range& r, std::uint32_t mid, Range& left, Range& right);
    void childRangesFromBins(const Range& r, std::uint32_t mid, const Bins& bins, int axis, int plane, int binCount,
                             Range& left, Range& right);
    bool keepsDepthBound(const Range& r, std::uint32_t leftSize) const;
    // Builds the subtree of r into nodes taken from `alloc`; returns its root.
    std::uint32_t buildSubtree(const Range& r, BuildNode* nodes, NodeAllocator& alloc);

    std::span<PrimRef> refs_;
    const SahParams& p_;
    ThreadPool& pool_;
    const SubtreeDone& done_;
};

void Builder::childRanges(const Range& r, std::uint32_t mid, Range& left, Range& right) {
    Bounds2 l, rb;
    for (std::uint32_t i = r.begin; i < mid; ++i) l.add(refs_[i]);
    for (std::uint32_t i = mid; i < r.end; ++i) rb.add(refs_[i]);
    left = {r.begin, mid, l.bounds, l.centroids, r.level + 1};
    right = {mid, r.end, rb.bounds, rb.centroids, r.level + 1};
}

// The same children as childRanges after a binned partition, their boxes taken from the bins: the
// bins of the split axis below the plane hold exactly the left child's references (binning and
// partitioning map a reference to the same bin), and min/max are exact, so the boxes are
// identical. Only the centroid bounds need a pass over the references (commit f79e8ba,
// docs/lab/2026-12-02-bvh-build.md).
void Builder::childRangesFromBins(const Range& r, std::uint32_t mid, const Bins& bins, int axis, int plane,
                                  int binCount, Range& left, Range& right) {
    Box4 lb, rb, lc, rc;
    for (int b = 0; b < plane; ++b) lb.grow(bins.lo[axis][b], bins.hi[axis][b]);
    for (int b = plane; b < binCount; ++b) rb.grow(bins.lo[axis][b], bins.hi[axis][b]);
    for (std::uint32_t i = r.begin; i < mid; ++i) lc.growPoint(refs_[i].centroid2());
    for (std::uint32_t i = mid; i < r.end; ++i) rc.growPoint(refs_[i].centroid2());
    left = {r.begin, mid, lb, lc, r.level + 1};
    right = {mid, r.end, rb, rc, r.level + 1};
}

// Two partitions, chosen by who calls (never by the thread count): subtree jobs use a branch-free
// Lomuto partition (whether a reference goes left is a coin flip for the branch predictor, so
// every reference is swapped and the boundary advanced by the comparison's 0 or 1); the top phase
// uses Hoare's, which moves fewer references through memory for the large ranges it handles.
void Builder::partitionByBin(const Range& r, const BinMapper::Axis& map, int plane, bool branchFree, const Bins* bins,
                             Range& left, Range& right) {
    if (branchFree) {
        PrimRef* base = refs_.data() + r.begin;
        std::uint32_t l = 0;  // [0, l) go left, [l, i) go right
        const std::uint32_t n = r.size();
        for (std::uint32_t i = 0; i < n; ++i) {
            // Whole 32-byte moves (memcpy), the side read from the array: with x as a value the
            // compiler spilled it to the stack to read its axis lane, and stored it into base[l]
            // as two 16-byte halves that the next iteration's 32-byte load of base[l] (the same
            // slot when x went right) could not be forwarded from: a stall per reference
            // (commit 098522a, docs/lab/2026-12-02-bvh-build.md).
            const auto goesLeft = static_cast<std::uint32_t>(map(base[i]) < plane);
            alignas(32) unsigned char x[sizeof(PrimRef)], front[sizeof(PrimRef)];
            std::memcpy(x, base + i, sizeof x);
            std::memcpy(front, base + l, sizeof front);
            std::memcpy(base + i, front, sizeof front);
            std::memcpy(base + l, x, sizeof x);
            l += goesLeft;
        }
        if (bins) childRangesFromBins(r, r.begin + l, *bins, map.axis, plane, p_.bins, left, right);
        else childRanges(r, r.begin + l, left, right);
        return;
    }
    Bounds2 l, rb;
    PrimRef* lo = refs_.data() + r.begin;
    PrimRef* hi = refs_.data() + r.end;
    auto goesLeft = [&](const PrimRef& ref) { return map(ref) < plane; };
    for (;;) {
        while (lo < hi && goesLeft(*lo)) l.add(*lo++);
        while (lo < hi && !goesLeft(hi[-1])) rb.add(*--hi);
        if (lo >= hi) break;
        std::swap(*lo, hi[-1]);
        l.add(*lo++);
        rb.add(*--hi);
    }
    const auto mid = static_cast<std::uint32_t>(lo - refs_.data());
    left = {r.begin, mid, l.bounds, l.centroids, r.level + 1};
    right = {mid, r.end, rb.bounds, rb.centroids, r.level + 1};
}

void Builder::splitMedian(const Range& r, Range& left, Range& right) {
    alignas(16) float ext[4];
    _mm_store_ps(ext, _mm_sub_ps(r.centroids.hi, r.centroids.lo));
    int axis = 0;
    if (ext[1] > ext[axis]) axis = 1;
    if (ext[2] > ext[axis]) axis = 2;
    const std::uint32_t mid = r.begin + r.size() / 2;
    if (ext[axis] > 0.0f) {
        auto key = [axis](const PrimRef& ref) { return lane(ref.centroid2(), axis); };
        std::nth_element(refs_.begin() + r.begin, refs_.begin() + mid, refs_.begin() + r.end,
                         [&](const PrimRef& a, const PrimRef& b) { return key(a) < key(b); });
    }
    childRanges(r, mid, left, right);
}

// The depth bound wins over the SAH: a child that could not fit below maxDepth with median
// splits sends its parent to a median split instead.
bool Builder::keepsDepthBound(const Range& r, std::uint32_t leftSize) const {
    const auto maxLeaf = static_cast<std::uint32_t>(p_.maxLeafSize);
    const int room = p_.maxDepth - r.level;  // levels left below this node
    const bool fits = levelsNeeded(leftSize, maxLeaf) <= room && levelsNeeded(r.size() - leftSize, maxLeaf) <= room;
    return fits || levelsNeeded(r.size(), maxLeaf) > room + 1;  // if even median splits cannot fit, keep the SAH
}

// A node of at most kSweepSize references: the swept split, its references put in centroid order
// when it is taken.
bool Builder::splitSmall(const Range& r, Range& left, Range& right) {
    const std::uint32_t n = r.size();
    PrimRef* base = refs_.data() + r.begin;
    SweepOrder order;
    const Split best = bestSweptSplit(base, n, r.bounds, r.centroids, p_, order);
    if (staysLeaf(n, best, p_)) return false;
    if (best.axis < 0 || !keepsDepthBound(r, static_cast<std::uint32_t>(best.plane))) {
        splitMedian(r, left, right);
        return true;
    }
    std::array<PrimRef, kSweepSize> sorted;
    for (std::uint32_t i = 0; i < n; ++i) sorted[i] = base[order[i]];
    std::copy(sorted.begin(), sorted.begin() + n, base);
    childRanges(r, r.begin + static_cast<std::uint32_t>(best.plane), left, right);
    return true;
}

Decision Builder::decideLarge(const Range& r, const Bins& bins, const BinMapper& mapper) const {
    const std::uint32_t n = r.size();
    const float area = r.bounds.halfArea();
    const Split s = area > 0.0f && mapper.anyUsable() ? bestBinnedSplit(bins, mapper, area, p_) : Split{};
    if (staysLeaf(n, s, p_)) return {Decision::Leaf};
    if (s.axis < 0) return {Decision::Median};
    return {Decision::Binned, s.axis, s.plane};
}

void Builder::apply(const Range& r, const Decision& d, const BinMapper& mapper, bool branchFree, Range& left,
                    Range& right, const Bins* bins) {
    if (d.kind == Decision::Median) {
        splitMedian(r, left, right);
        return;
    }
    partitionByBin(r, mapper.axis(d.axis), d.plane, branchFree, bins, left, right);
    if (left.size() == 0 || right.size() == 0 || !keepsDepthBound(r, left.size())) splitMedian(r, left, right);
}

bool Builder::split(const Range& r, bool branchFree, Range& left, Range& right) {
    const std::uint32_t n = r.size();
    const auto maxLeaf = static_cast<std::uint32_t>(p_.maxLeafSize);
    if (n <= 1) return false;
    if (r.level > p_.maxDepth && n <= maxLeaf) return false;  // only reached when the depth bound is tight
    if (n <= kSweepSize) return splitSmall(r, left, right);
    BinMapper mapper(r.centroids, p_.bins);
    if (n <= kWidestAxisOnly) mapper.keepWidestAxis(r.centroids);
    Bins bins;
    if (mapper.anyUsable()) binRefs(refs_.data() + r.begin, n, mapper, bins);
    const Decision d = decideLarge(r, bins, mapper);
    if (d.kind == Decision::Leaf) return false;
    apply(r, d, mapper, branchFree, left, right, &bins);
    return true;
}

// The same bytes as BuildNode{box.lo, box.hi, a, b}, assembled in two SSE registers: built as a
// value, the node went through the stack as 4- and 8-byte stores read back by one 32-byte load,
// which cannot be store-forwarded (a stall twice per node; commit 93ae134,
// docs/lab/2026-12-02-bvh-build.md).
static_assert(offsetof(BuildNode, lo) == 0 && offsetof(BuildNode, hi) == 12 && offsetof(BuildNode, a) == 24 &&
              offsetof(BuildNode, b) == 28);
inline void storeNode(BuildNode* dst, const Box4& box, std::uint32_t a, std::uint32_t b) {
    const __m128 links = _mm_castsi128_ps(_mm_setr_epi32(static_cast<int>(a), static_cast<int>(b), 0, 0));
    auto* f = reinterpret_cast<float*>(dst);
    _mm_storeu_ps(f, _mm_insert_ps(box.lo, box.hi, 0x30));                            // lo.xyz, hi.x
    _mm_storeu_ps(f + 4, _mm_shuffle_ps(box.hi, links, _MM_SHUFFLE(1, 0, 2, 1)));  // hi.yz, a, b
}

std::uint32_t Builder::buildSubtree(const Range& r, BuildNode* nodes, NodeAllocator& alloc) {
    const std::uint32_t index = alloc.take();
    storeNode(nodes + index, r.bounds, r.begin, BuildNode::kLeafBit | r.size());
    Range left, right;
    if (!split(r, true, left, right)) return index;
    const std::uint32_t l = buildSubtree(left, nodes, alloc);
    const std::uint32_t rr = buildSubtree(right, nodes, alloc);
    storeNode(nodes + index, r.bounds, l, rr);
    return index;
}

BuildTree Builder::run() {
    BuildTree tree;
    const auto n = static_cast<std::uint32_t>(refs_.size());
    if (n == 0) return tree;

    Range root{0, n, {}, {}, 1};
    {
        const std::uint32_t chunks = (n + kBinChunk - 1) / kBinChunk;
        std::vector<Bounds2> partial(chunks);
        pool_.parallelFor(chunks, [&](std::size_t c) {
            const std::uint32_t b = static_cast<std::uint32_t>(c) * kBinChunk;
            const std::uint32_t e = std::min(n, b + kBinChunk);
            for (std::uint32_t i = b; i < e; ++i) partial[c].add(refs_[i]);
        });
        for (const Bounds2& b : partial) {
            root.bounds.grow(b.bounds);
            root.centroids.grow(b.centroids);
        }
    }

    // Top phase, level by level: ranges above kParallelNodeSize are binned in chunks spread over
    // the pool, then partitioned side by side (one range per thread, the same in-place partition
    // a single thread uses); smaller ranges become subtree jobs. Which ranges take this path
    // depends only on their size, never on the thread count, so the tree is the same for any.
    struct Job {
        Range range;
        std::uint32_t parent;  // top node index, or UINT32_MAX for the root
        bool rightSide;
        std::uint32_t root = 0, inner = 0;
    };
    std::vector<Job> jobs;
    std::vector<BuildNode> top;
    std::vector<Job> frontier{{root, UINT32_MAX, false}};
    while (!frontier.empty()) {
        std::vector<Job> big;
        for (const Job& j : frontier) (j.range.size() > kParallelNodeSize ? big : jobs).push_back(j);
        frontier.clear();
        if (big.empty()) break;
        std::vector<BinMapper> mappers;
        std::vector<std::pair<std::size_t, std::uint32_t>> chunks;  // (range, first reference)
        for (std::size_t i = 0; i < big.size(); ++i) {
            mappers.emplace_back(big[i].range.centroids, p_.bins);
            for (std::uint32_t b = big[i].range.begin; b < big[i].range.end; b += kBinChunk) chunks.push_back({i, b});
        }
        std::vector<Bins> partial(chunks.size());
        pool_.parallelFor(chunks.size(), [&](std::size_t c) {
            const auto [i, b] = chunks[c];
            const std::uint32_t e = std::min(big[i].range.end, b + kBinChunk);
            if (mappers[i].anyUsable()) binRefs(refs_.data() + b, e - b, mappers[i], partial[c]);
            else partial[c].reset(p_.bins);
        });
        std::vector<Decision> decisions(big.size());
        for (std::size_t i = 0, c = 0; i < big.size(); ++i) {
            Bins& bins = partial[c++];
            for (; c < chunks.size() && chunks[c].first == i; ++c) bins.merge(partial[c], p_.bins);
            decisions[i] = decideLarge(big[i].range, bins, mappers[i]);
        }
        std::vector<std::pair<Range, Range>> children(big.size());
        pool_.parallelFor(big.size(), [&](std::size_t i) {
            apply(big[i].range, decisions[i], mappers[i], false, children[i].first, children[i].second);
        });
        for (std::size_t i = 0; i < big.size(); ++i) {
            const auto index = static_cast<std::uint32_t>(top.size());
            const Aabb box = big[i].range.bounds.toAabb();
            top.push_back(BuildNode::innerNode(box, 0, 0));
            if (big[i].parent != UINT32_MAX) (big[i].rightSide ? top[big[i].parent].b : top[big[i].parent].a) = index;
            frontier.push_back({children[i].first, index, false});
            frontier.push_back({children[i].second, index, true});
        }
    }

    // One array: the top nodes, then room for every job's worst case (2m - 1 nodes for m
    // references), handed out by NodeAllocator. Huge pages: on this VM a first touch costs
    // 0.7 ms/MB with 4 KiB pages and 0.13 ms/MB with 2 MiB pages.
    std::size_t capacity = top.size();
    for (const Job& job : jobs) capacity += 2 * std::size_t{job.range.size()} - 1;
    tree.nodes = HugeArray<BuildNode>(capacity);
    std::atomic<std::uint32_t> cursor{static_cast<std::uint32_t>(top.size())};
    std::copy(top.begin(), top.end(), tree.nodes.get());
    // Largest jobs first, so the last job to finish is a small one.
    std::vector<std::size_t> order(jobs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return jobs[a].range.size() > jobs[b].range.size(); });
    pool_.parallelFor(jobs.size(), [&](std::size_t k) {
        Job& job = jobs[order[k]];
        NodeAllocator alloc(cursor, 2 * job.range.size() - 1);
        job.root = buildSubtree(job.range, tree.nodes.get(), alloc);
        job.inner = (alloc.taken() - 1) / 2;  // a full binary tree: inner = leaves - 1
        if (done_) done_(job.range.begin, job.range.end);
    });
    tree.root = 0;
    tree.topCount = static_cast<std::uint32_t>(top.size());
    for (const Job& job : jobs) {
        if (job.parent == UINT32_MAX) tree.root = job.root;
        else (job.rightSide ? tree.nodes[job.parent].b : tree.nodes[job.parent].a) = job.root;
        tree.subtreeRoots.push_back(job.root);
        tree.subtreeInnerNodes.push_back(job.inner);
    }
    return tree;
}

}  // namespace

BuildTree buildSah(std::span<PrimRef> refs, const SahParams& params, ThreadPool& pool, const SubtreeDone& subtreeDone) {
    if (params.bins < 2 || params.bins > kMaxBins)
        throw std::invalid_argument("bvh: bins must be in [2, " + std::to_string(kMaxBins) + "], got " +
                                    std::to_string(params.bins));
    if (refs.size() >= (std::size_t{1} << 30))
        throw std::invalid_argument("bvh: a group of " + std::to_string(refs.size()) + " primitives exceeds the 2^30 the builder supports");
    if (params.maxLeafSize < 1)
        throw std::invalid_argument("bvh: maxLeafSize must be >= 1, got " + std::to_string(params.maxLeafSize));
    if (!(params.traversalCost >= 0.0f) || !(params.intersectionCost > 0.0f))
        throw std::invalid_argument("bvh: SAH costs must be traversal >= 0 and intersection > 0");
    // A bound below the levels that median splits need for these references is raised to them:
    // otherwise no split could keep it and the SAH would be kept everywhere, unbounded (the CPU
    // traversal's stack, wide_bvh.h kWideStackSize, and the kernel's rely on the bound). At most
    // 30 levels for the 2^30 references allowed, so a tree stays within kMaxTreeDepth (64).
    SahParams bounded = params;
    bounded.maxDepth = std::max(params.maxDepth, levelsNeeded(static_cast<std::uint32_t>(refs.size()),
                                                              static_cast<std::uint32_t>(params.maxLeafSize)));
    return Builder(refs, bounded, pool, subtreeDone).run();
}

}  // namespace vkrt::bvh
