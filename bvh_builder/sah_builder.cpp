#include "sah_builder.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace vkrt::bvh {

namespace {

constexpr int kMaxBins = 64;
// Above this many references a node's binning is spread over the pool, and its children are
// split further before being handed out as subtree jobs; below it one thread builds the subtree.
constexpr std::uint32_t kParallelNodeSize = 16 * 1024;
// References per binning chunk: large enough that merging bins is negligible.
constexpr std::uint32_t kBinChunk = 8 * 1024;

// A range of references still to be turned into a subtree. Boxes: geometry, and twice the centroids.
struct Range {
    std::uint32_t begin = 0, end = 0;
    Box4 bounds, centroids;
    int level = 0;  // inner-node level this range's node would sit at (root = 1)
    std::uint32_t size() const { return end - begin; }
};

// Maps twice-centroids to bin indices per axis. Shared by binning and partitioning so both put a
// reference in the same bin.
struct BinMapper {
    __m128 origin;
    __m128 scale;
    int bins = 0;
    std::array<bool, 3> usable{};

    BinMapper(const Box4& centroids, int binCount) : bins(binCount) {
        origin = centroids.lo;
        alignas(16) float lo[4], hi[4], s[4] = {0, 0, 0, 0};
        _mm_store_ps(lo, centroids.lo);
        _mm_store_ps(hi, centroids.hi);
        for (int a = 0; a < 3; ++a) {
            const float extent = hi[a] - lo[a];
            // (1 - 2^-20) keeps the largest centroid inside the last bin despite rounding.
            const float k = extent > 0.0f ? static_cast<float>(binCount) * (1.0f - 0x1p-20f) / extent : 0.0f;
            usable[a] = extent > 0.0f && k < 1e30f;  // a denormal extent would give an infinite scale
            s[a] = usable[a] ? k : 0.0f;
        }
        scale = _mm_load_ps(s);
    }
    bool anyUsable() const { return usable[0] || usable[1] || usable[2]; }
    // Bin index per axis; unusable axes map everything to bin 0.
    __m128i binOf(__m128 centroid2) const {
        __m128 f = _mm_mul_ps(_mm_sub_ps(centroid2, origin), scale);
        f = _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(static_cast<float>(bins - 1)));
        return _mm_cvttps_epi32(f);
    }
    int binOf(__m128 centroid2, int axis) const {
        alignas(16) std::int32_t b[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(b), binOf(centroid2));
        return b[axis];
    }
};

struct Bins {
    std::array<std::array<Box4, kMaxBins>, 3> box;
    std::array<std::array<std::uint32_t, kMaxBins>, 3> count{};

    void add(std::span<const PrimRef> refs, const BinMapper& mapper) {
        alignas(16) std::int32_t b[4];
        for (const PrimRef& r : refs) {
            _mm_store_si128(reinterpret_cast<__m128i*>(b), mapper.binOf(r.centroid2()));
            box[0][b[0]].grow(r.lo, r.hi);
            ++count[0][b[0]];
            box[1][b[1]].grow(r.lo, r.hi);
            ++count[1][b[1]];
            box[2][b[2]].grow(r.lo, r.hi);
            ++count[2][b[2]];
        }
    }
    void merge(const Bins& o, int bins) {
        for (int a = 0; a < 3; ++a)
            for (int i = 0; i < bins; ++i) {
                box[a][i].grow(o.box[a][i]);
                count[a][i] += o.count[a][i];
            }
    }
};

struct Split {
    int axis = -1;  // -1: no SAH split found
    int bin = 0;    // references with bin index < bin go left
    float cost = 0.0f;
};

Split bestSplit(const Bins& bins, const BinMapper& mapper, float nodeArea, const SahParams& p) {
    Split best;
    std::array<float, kMaxBins> rightArea{};
    std::array<std::uint32_t, kMaxBins> rightCount{};
    for (int a = 0; a < 3; ++a) {
        if (!mapper.usable[a]) continue;
        Box4 acc;
        std::uint32_t n = 0;
        for (int i = mapper.bins - 1; i > 0; --i) {  // rightArea[i]: bins [i, bins)
            acc.grow(bins.box[a][i]);
            n += bins.count[a][i];
            rightArea[i] = acc.halfArea();
            rightCount[i] = n;
        }
        acc = Box4{};
        n = 0;
        for (int i = 1; i < mapper.bins; ++i) {  // plane i: bins [0, i) left
            acc.grow(bins.box[a][i - 1]);
            n += bins.count[a][i - 1];
            if (n == 0 || rightCount[i] == 0) continue;
            const float cost = p.traversalCost + p.intersectionCost *
                (acc.halfArea() * static_cast<float>(n) + rightArea[i] * static_cast<float>(rightCount[i])) / nodeArea;
            if (best.axis < 0 || cost < best.cost) best = {a, i, cost};
        }
    }
    return best;
}

// Smallest number of inner-node levels that can hold n references with median splits.
int levelsNeeded(std::uint32_t n, std::uint32_t maxLeaf) {
    int levels = 0;
    while (n > maxLeaf) {
        n = (n + 1) / 2;
        ++levels;
    }
    return levels;
}

struct Bounds2 {
    Box4 bounds, centroids;
    void add(const PrimRef& r) {
        bounds.grow(r.lo, r.hi);
        centroids.growPoint(r.centroid2());
    }
};

class Builder {
public:
    Builder(std::span<PrimRef> refs, const SahParams& p, ThreadPool& pool) : refs_(refs), p_(p), pool_(pool) {}

    BuildTree run();

private:
    // Decides how to split a range: returns the position of the first right reference and the
    // children's ranges, or false when the range becomes a leaf.
    bool split(const Range& r, bool parallel, Range& left, Range& right);
    Bins binParallel(const Range& r, const BinMapper& mapper);
    void partitionByBin(const Range& r, const BinMapper& mapper, int axis, int bin, Range& left, Range& right);
    void splitMedian(const Range& r, Range& left, Range& right);
    std::uint32_t buildSubtree(const Range& r, std::vector<BuildNode>& nodes);

    std::span<PrimRef> refs_;
    const SahParams& p_;
    ThreadPool& pool_;
};

void Builder::partitionByBin(const Range& r, const BinMapper& mapper, int axis, int bin, Range& left, Range& right) {
    Bounds2 l, rb;
    PrimRef* lo = refs_.data() + r.begin;
    PrimRef* hi = refs_.data() + r.end;
    auto goesLeft = [&](const PrimRef& ref) { return mapper.binOf(ref.centroid2(), axis) < bin; };
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
        auto key = [axis](const PrimRef& ref) {
            alignas(16) float c[4];
            _mm_store_ps(c, ref.centroid2());
            return c[axis];
        };
        std::nth_element(refs_.begin() + r.begin, refs_.begin() + mid, refs_.begin() + r.end,
                         [&](const PrimRef& a, const PrimRef& b) { return key(a) < key(b); });
    }
    Bounds2 l, rb;
    for (std::uint32_t i = r.begin; i < mid; ++i) l.add(refs_[i]);
    for (std::uint32_t i = mid; i < r.end; ++i) rb.add(refs_[i]);
    left = {r.begin, mid, l.bounds, l.centroids, r.level + 1};
    right = {mid, r.end, rb.bounds, rb.centroids, r.level + 1};
}

Bins Builder::binParallel(const Range& r, const BinMapper& mapper) {
    const std::uint32_t chunks = (r.size() + kBinChunk - 1) / kBinChunk;
    std::vector<Bins> partial(chunks);
    pool_.parallelFor(chunks, [&](std::size_t c) {
        const std::uint32_t b = r.begin + static_cast<std::uint32_t>(c) * kBinChunk;
        const std::uint32_t e = std::min(r.end, b + kBinChunk);
        partial[c].add(refs_.subspan(b, e - b), mapper);
    });
    for (std::uint32_t c = 1; c < chunks; ++c) partial[0].merge(partial[c], mapper.bins);
    return partial[0];
}

bool Builder::split(const Range& r, bool parallel, Range& left, Range& right) {
    const std::uint32_t n = r.size();
    const auto maxLeaf = static_cast<std::uint32_t>(p_.maxLeafSize);
    if (n <= 1) return false;
    if (r.level > p_.maxDepth && n <= maxLeaf) return false;  // only reached when the depth bound is tight
    const BinMapper mapper(r.centroids, p_.bins);
    const float leafCost = p_.intersectionCost * static_cast<float>(n);
    if (!mapper.anyUsable()) {
        if (n <= maxLeaf) return false;
        splitMedian(r, left, right);
        return true;
    }
    Bins bins;
    if (parallel) bins = binParallel(r, mapper);
    else bins.add(refs_.subspan(r.begin, n), mapper);
    const float area = r.bounds.halfArea();
    const Split s = area > 0.0f ? bestSplit(bins, mapper, area, p_) : Split{};
    if (n <= maxLeaf && (s.axis < 0 || leafCost <= s.cost)) return false;
    if (s.axis < 0) {
        splitMedian(r, left, right);
        return true;
    }
    partitionByBin(r, mapper, s.axis, s.bin, left, right);
    // The depth bound wins over the SAH: a child that could not fit below maxDepth with median
    // splits sends this node to a median split instead.
    const int room = p_.maxDepth - r.level;  // levels left below this node
    const bool tooDeep = levelsNeeded(left.size(), maxLeaf) > room || levelsNeeded(right.size(), maxLeaf) > room;
    if (left.size() == 0 || right.size() == 0 || (tooDeep && levelsNeeded(n, maxLeaf) <= room + 1))
        splitMedian(r, left, right);
    return true;
}

std::uint32_t Builder::buildSubtree(const Range& r, std::vector<BuildNode>& nodes) {
    const auto index = static_cast<std::uint32_t>(nodes.size());
    nodes.push_back({r.bounds.toAabb(), 0, 0, r.begin, r.size()});
    Range left, right;
    if (!split(r, false, left, right)) return index;
    const std::uint32_t l = buildSubtree(left, nodes);
    const std::uint32_t rr = buildSubtree(right, nodes);
    nodes[index].left = l;
    nodes[index].right = rr;
    nodes[index].count = 0;
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

    // Top phase: nodes too big for one thread are split with parallel binning; the ranges left
    // over become subtree jobs. A job slot is recorded as (node, side) to patch after the jobs run.
    struct Job {
        Range range;
        std::uint32_t parent;  // index in tree.nodes, or UINT32_MAX for the root
        bool rightSide;
        std::vector<BuildNode> nodes;
        std::uint32_t localRoot = 0;
    };
    std::vector<Job> jobs;
    const bool parallel = pool_.size() > 1;
    std::vector<std::pair<Range, std::pair<std::uint32_t, bool>>> pending{{root, {UINT32_MAX, false}}};
    while (!pending.empty()) {
        auto [range, slot] = pending.back();
        pending.pop_back();
        Range left, right;
        if (!parallel || range.size() <= kParallelNodeSize || !split(range, true, left, right)) {
            jobs.push_back({range, slot.first, slot.second, {}, 0});
            continue;
        }
        const auto index = static_cast<std::uint32_t>(tree.nodes.size());
        tree.nodes.push_back({range.bounds.toAabb(), 0, 0, range.begin, 0});
        if (slot.first != UINT32_MAX) (slot.second ? tree.nodes[slot.first].right : tree.nodes[slot.first].left) = index;
        pending.push_back({right, {index, true}});
        pending.push_back({left, {index, false}});
    }
    // Largest jobs first, so the last job to finish is a small one.
    std::vector<std::size_t> order(jobs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return jobs[a].range.size() > jobs[b].range.size(); });
    pool_.parallelFor(jobs.size(), [&](std::size_t k) {
        Job& job = jobs[order[k]];
        job.localRoot = buildSubtree(job.range, job.nodes);
    });

    // Append the jobs' nodes (in job order, which does not depend on the thread count).
    tree.root = 0;
    for (Job& job : jobs) {
        const auto offset = static_cast<std::uint32_t>(tree.nodes.size());
        for (BuildNode node : job.nodes) {
            if (!node.leaf()) {
                node.left += offset;
                node.right += offset;
            }
            tree.nodes.push_back(node);
        }
        const std::uint32_t jobRoot = offset + job.localRoot;
        if (job.parent == UINT32_MAX) tree.root = jobRoot;
        else (job.rightSide ? tree.nodes[job.parent].right : tree.nodes[job.parent].left) = jobRoot;
    }
    return tree;
}

}  // namespace

BuildTree buildSah(std::span<PrimRef> refs, const SahParams& params, ThreadPool& pool) {
    if (params.bins < 2 || params.bins > kMaxBins)
        throw std::invalid_argument("bvh: bins must be in [2, " + std::to_string(kMaxBins) + "], got " +
                                    std::to_string(params.bins));
    if (params.maxLeafSize < 1)
        throw std::invalid_argument("bvh: maxLeafSize must be >= 1, got " + std::to_string(params.maxLeafSize));
    if (!(params.traversalCost >= 0.0f) || !(params.intersectionCost > 0.0f))
        throw std::invalid_argument("bvh: SAH costs must be traversal >= 0 and intersection > 0");
    return Builder(refs, params, pool).run();
}

double sahCost(const BuildTree& tree, const SahParams& params) {
    if (tree.nodes.empty()) return 0.0;
    const double rootArea = tree.nodes[tree.root].box.halfArea();
    if (rootArea <= 0.0) return params.intersectionCost * tree.nodes[tree.root].count;
    // Summed in depth-first order from the root (not storage order, which depends on which
    // thread built what), so the figure is identical for any thread count.
    double cost = 0.0;
    std::vector<std::uint32_t> stack{tree.root};
    while (!stack.empty()) {
        const BuildNode& node = tree.nodes[stack.back()];
        stack.pop_back();
        const double a = node.box.halfArea() / rootArea;
        if (node.leaf()) {
            cost += params.intersectionCost * node.count * a;
        } else {
            cost += params.traversalCost * a;
            stack.push_back(node.right);
            stack.push_back(node.left);
        }
    }
    return cost;
}

int innerDepth(const BuildTree& tree) {
    if (tree.nodes.empty()) return 0;
    int deepest = 0;
    std::vector<std::pair<std::uint32_t, int>> stack{{tree.root, 0}};
    while (!stack.empty()) {
        auto [i, d] = stack.back();
        stack.pop_back();
        const BuildNode& node = tree.nodes[i];
        if (node.leaf()) {
            deepest = std::max(deepest, d);
            continue;
        }
        stack.push_back({node.left, d + 1});
        stack.push_back({node.right, d + 1});
    }
    return deepest;
}

}  // namespace vkrt::bvh
