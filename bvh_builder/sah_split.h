// The SAH builder's split rule (Wald 2007, "On fast Construction of SAH-based Bounding Volume
// Hierarchies"): where a node may be split, what a split and a leaf cost, when a node stays a
// leaf. sah_builder.h builds the tree with it (and bounds its depth); docs/BVH.md §2 gives the why.
//  - Candidates: `bins` equal-width bins over the centroid bounds on each of the 3 axes (on the
//    widest centroid axis only at most kWidestAxisOnly references), a plane between each two
//    non-empty bins; at most kSweepSize references: every plane between consecutive centroids
//    along the widest centroid axis (on that axis a superset of the planes 16 bins could offer).
//  - Cost of a split: C_trav + C_isect * (A_left * N_left + A_right * N_right) / A_node (splitCost);
//    cost of a leaf: C_isect * N (leafCost). The cheapest plane wins; ties: the lowest axis, then
//    the lowest plane.
//  - A node stays a leaf when it holds at most maxLeafSize primitives and no split is cheaper than
//    the leaf (staysLeaf).
#pragma once

#include <immintrin.h>

#include <array>
#include <cstdint>

#include "aabb.h"

namespace vkrt::bvh {

struct SahParams {
    int bins = 16;
    int maxLeafSize = 8;
    float traversalCost = 1.0f;     // C_trav
    float intersectionCost = 1.0f;  // C_isect
    int maxDepth = 64;  // inner-node levels, root = 1 (the builder's bound, sah_builder.h)
};

constexpr int kMaxBins = 64;
// Nodes with at most this many references use the exact sweep instead of bins.
constexpr std::uint32_t kSweepSize = 16;
// Nodes with at most this many references bin only their widest centroid axis.
constexpr std::uint32_t kWidestAxisOnly = 64;

inline float lane(__m128 v, int i) {
    alignas(16) float f[4];
    _mm_store_ps(f, v);
    return f[i];
}

// Half the surface area of a box held in SSE registers, without leaving them.
inline float halfArea(__m128 lo, __m128 hi) {
    const __m128 e = _mm_max_ps(_mm_sub_ps(hi, lo), _mm_setzero_ps());
    const __m128 eYZX = _mm_shuffle_ps(e, e, _MM_SHUFFLE(3, 0, 2, 1));
    const __m128 p = _mm_mul_ps(e, eYZX);  // xy, yz, zx, -
    const __m128 sum = _mm_add_ss(p, _mm_add_ss(_mm_shuffle_ps(p, p, 1), _mm_movehl_ps(p, p)));
    return _mm_cvtss_f32(sum);
}

// areaScale = C_isect / A_node, computed once per node.
inline float splitCost(const SahParams& p, float areaScale, float leftArea, std::uint32_t leftCount, float rightArea,
                       std::uint32_t rightCount) {
    return p.traversalCost +
           areaScale * (leftArea * static_cast<float>(leftCount) + rightArea * static_cast<float>(rightCount));
}
inline float leafCost(const SahParams& p, std::uint32_t n) { return p.intersectionCost * static_cast<float>(n); }

// Maps twice-centroids to bin indices per axis. Binning and partitioning use the same arithmetic
// (the SSE lanes here, the scalar Axis below: IEEE operations give the same bits), so a reference
// is partitioned into the bin it was counted in.
struct BinMapper {
    __m128 origin;
    __m128 scale;
    int bins = 0;
    std::array<bool, 3> usable{};

    BinMapper(const Box4& centroids, int binCount) : bins(binCount) {
        origin = centroids.lo;
        alignas(16) float s[4] = {0, 0, 0, 0};
        for (int a = 0; a < 3; ++a) {
            const float extent = lane(centroids.hi, a) - lane(centroids.lo, a);
            // (1 - 2^-20) keeps the largest centroid inside the last bin despite rounding.
            const float k = extent > 0.0f ? static_cast<float>(binCount) * (1.0f - 0x1p-20f) / extent : 0.0f;
            usable[a] = extent > 0.0f && k < 1e30f;  // a denormal extent would give an infinite scale
            s[a] = usable[a] ? k : 0.0f;
        }
        scale = _mm_load_ps(s);
    }
    bool anyUsable() const { return usable[0] || usable[1] || usable[2]; }
    // Keeps only the usable axis of largest centroid extent (see kWidestAxisOnly).
    void keepWidestAxis(const Box4& centroids) {
        int w = -1;
        for (int a = 0; a < 3; ++a)
            if (usable[a] && (w < 0 || lane(centroids.hi, a) - lane(centroids.lo, a) >
                                           lane(centroids.hi, w) - lane(centroids.lo, w)))
                w = a;
        for (int a = 0; a < 3; ++a) usable[a] = a == w;
    }
    // Bin index per axis; unusable axes map everything to bin 0.
    __m128i binOf(__m128 centroid2) const {
        __m128 f = _mm_mul_ps(_mm_sub_ps(centroid2, origin), scale);
        f = _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), _mm_set1_ps(static_cast<float>(bins - 1)));
        return _mm_cvttps_epi32(f);
    }
    struct Axis {
        float origin, scale, last;
        int axis;
        int operator()(const PrimRef& r) const {
            const float* lo = reinterpret_cast<const float*>(&r.lo);
            const float* hi = reinterpret_cast<const float*>(&r.hi);
            const float f = ((lo[axis] + hi[axis]) - origin) * scale;
            // binOf's clamp, operand for operand (maxps/minps return the second operand when the
            // first is NaN): a NaN from bounds whose lo + hi overflows (inf - inf, inf * 0) goes to
            // bin 0 in both paths, never to a cast of NaN (issue 38: a bin index of -2^31).
            const float atLeast0 = f > 0.0f ? f : 0.0f;
            return static_cast<int>(atLeast0 < last ? atLeast0 : last);
        }
    };
    Axis axis(int a) const { return {lane(origin, a), lane(scale, a), static_cast<float>(bins - 1), a}; }
};

// Per-axis bins; only the first `bins` entries of each axis are reset and read.
struct Bins {
    __m128 lo[3][kMaxBins], hi[3][kMaxBins];
    std::uint32_t count[3][kMaxBins];

    void reset(int bins, int onlyAxis = -1) {
        const __m128 big = _mm_set1_ps(FLT_MAX), small = _mm_set1_ps(-FLT_MAX);
        for (int a = 0; a < 3; ++a) {
            if (onlyAxis >= 0 && a != onlyAxis) continue;
            for (int i = 0; i < bins; ++i) {
                lo[a][i] = big;
                hi[a][i] = small;
                count[a][i] = 0;
            }
        }
    }
    void addAxis(const PrimRef& r, int b, int a) {
        lo[a][b] = _mm_min_ps(lo[a][b], r.lo);
        hi[a][b] = _mm_max_ps(hi[a][b], r.hi);
        ++count[a][b];
    }
    void add(const PrimRef& r, const BinMapper& mapper) {
        // Lanes are extracted in registers: storing the vector and reloading single lanes would
        // defeat store-to-load forwarding and stall every reference.
        const __m128i bin = mapper.binOf(r.centroid2());
        const int b[3] = {_mm_cvtsi128_si32(bin), _mm_extract_epi32(bin, 1), _mm_extract_epi32(bin, 2)};
        for (int a = 0; a < 3; ++a) {
            lo[a][b[a]] = _mm_min_ps(lo[a][b[a]], r.lo);
            hi[a][b[a]] = _mm_max_ps(hi[a][b[a]], r.hi);
            ++count[a][b[a]];
        }
    }
    // The same update as add(), the bin indices computed beforehand (lanes 0-2 of `bin`).
    void addAt(const PrimRef& r, const std::int32_t* bin) {
        for (int a = 0; a < 3; ++a) {
            lo[a][bin[a]] = _mm_min_ps(lo[a][bin[a]], r.lo);
            hi[a][bin[a]] = _mm_max_ps(hi[a][bin[a]], r.hi);
            ++count[a][bin[a]];
        }
    }
    void merge(const Bins& o, int bins) {
        for (int a = 0; a < 3; ++a)
            for (int i = 0; i < bins; ++i) {
                lo[a][i] = _mm_min_ps(lo[a][i], o.lo[a][i]);
                hi[a][i] = _mm_max_ps(hi[a][i], o.hi[a][i]);
                count[a][i] += o.count[a][i];
            }
    }
};

// Bins a run of references (every bin of the usable axes reset first).
void binRefs(const PrimRef* refs, std::uint32_t n, const BinMapper& mapper, Bins& out);

struct Split {
    int axis = -1;  // -1: no split found
    int plane = 0;  // bins: references with bin index < plane go left; sweep: the first `plane` in order
    float cost = 0.0f;
};

inline bool staysLeaf(std::uint32_t n, const Split& best, const SahParams& p) {
    return n <= static_cast<std::uint32_t>(p.maxLeafSize) && (best.axis < 0 || leafCost(p, n) <= best.cost);
}

// The cheapest plane between non-empty bins (nodeArea > 0).
Split bestBinnedSplit(const Bins& bins, const BinMapper& mapper, float nodeArea, const SahParams& p);

// The cheapest plane between consecutive centroids of refs[0, n), n <= kSweepSize, along the widest
// centroid axis; `order` receives the references' positions in centroid order (valid when a split
// is found: plane = how many of them go left).
using SweepOrder = std::array<std::uint8_t, kSweepSize>;
Split bestSweptSplit(const PrimRef* refs, std::uint32_t n, const Box4& bounds, const Box4& centroids, const SahParams& p,
                     SweepOrder& order);

}  // namespace vkrt::bvh
