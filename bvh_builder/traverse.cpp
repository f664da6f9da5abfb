// CPU traversal of the two-level BVH: intersectClosest / intersectAny of bvh.h.
// Ordered depth-first traversal with a fixed-size stack: at each node both children's boxes are
// tested (one 64-byte node read), leaves are intersected at once, the nearer inner child is visited
// first and the farther one pushed with its entry distance, so it is skipped if a closer hit has
// been found by the time it is popped.
#include <immintrin.h>

#include <cmath>
#include <cstring>

#include "bvh.h"
#include "intersect_inline.h"
#include "node_layout.h"

namespace vkrt::bvh {

namespace {

// Enough for any tree the builder makes: it bounds every level's depth by kMaxTreeDepth.
constexpr int kStackSize = 64;

// Slab test of both children of a node at once, in SSE (Kay & Kajiya 1986, with each axis's near
// plane chosen by the sign of the direction as in Williams et al. 2005, so an empty box, stored as
// lo = +FLT_MAX > hi = -FLT_MAX, always gives tNear > tFar). Direction components of magnitude
// below 2^-100 are replaced by +-2^-100: the inverse is then finite, so (plane - origin) * inverse
// is never 0 * inf = NaN, and the slab of an axis-parallel ray is (-huge, +huge) inside the slab
// and entirely on one side outside it (a conservative answer at worst).
struct NodeRay {
    __m128 oXXYY, iXXYY, oZZZZ, iZZZZ;
    __m128 swapXY;  // lanes (x: 0,1; y: 2,3) whose lo/hi planes swap roles: the direction is negative
    __m128 swapZ;   // the same for the z texel (lo0.z hi0.z lo1.z hi1.z)

    NodeRay(const glm::vec3& origin, const glm::vec3& dir) {
        float inv[3];
        for (int i = 0; i < 3; ++i) {
            const float d = std::abs(dir[i]) < 0x1p-100f ? std::copysign(0x1p-100f, dir[i]) : dir[i];
            inv[i] = 1.0f / d;
        }
        oXXYY = _mm_setr_ps(origin.x, origin.x, origin.y, origin.y);
        iXXYY = _mm_setr_ps(inv[0], inv[0], inv[1], inv[1]);
        oZZZZ = _mm_set1_ps(origin.z);
        iZZZZ = _mm_set1_ps(inv[2]);
        const float sx = inv[0] < 0.0f ? -1.0f : 0.0f, sy = inv[1] < 0.0f ? -1.0f : 0.0f;
        const float sz = inv[2] < 0.0f ? -1.0f : 0.0f;
        // All-ones lanes where a swap is needed (the sign bit is what blendv reads).
        swapXY = _mm_setr_ps(sx, sx, sy, sy);
        swapZ = _mm_set1_ps(sz);
    }
};

// Rounding in the slab test can shrink the interval by a few ulps and miss a primitive that
// touches its box's boundary; widening tFar by 1 + 2*gamma(3) makes the test conservative
// (Ize 2013, "Robust BVH Ray Traversal", JCGT 2(2)).
constexpr float kFarScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

// Returns a 2-bit mask of the children whose box the ray enters within [0, tmax]; tEntry gets
// their entry distances.
inline int slab2(const gpu::BvhNode& node, const NodeRay& r, float tmax, float tEntry[2]) {
    const float* f = reinterpret_cast<const float*>(&node);
    const __m128 xy0 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(f), r.oXXYY), r.iXXYY);
    const __m128 xy1 = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(f + 4), r.oXXYY), r.iXXYY);
    const __m128 z = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(f + 8), r.oZZZZ), r.iZZZZ);
    // (near, far) per axis: swap lo/hi lanes where the direction is negative.
    constexpr int kSwapPairs = _MM_SHUFFLE(2, 3, 0, 1);
    const __m128 s0 = _mm_blendv_ps(xy0, _mm_shuffle_ps(xy0, xy0, kSwapPairs), r.swapXY);  // nx0 fx0 ny0 fy0
    const __m128 s1 = _mm_blendv_ps(xy1, _mm_shuffle_ps(xy1, xy1, kSwapPairs), r.swapXY);  // nx1 fx1 ny1 fy1
    const __m128 sz = _mm_blendv_ps(z, _mm_shuffle_ps(z, z, kSwapPairs), r.swapZ);        // nz0 fz0 nz1 fz1
    const __m128 nearXY = _mm_shuffle_ps(s0, s1, _MM_SHUFFLE(2, 0, 2, 0));  // nx0 ny0 nx1 ny1
    const __m128 farXY = _mm_shuffle_ps(s0, s1, _MM_SHUFFLE(3, 1, 3, 1));   // fx0 fy0 fx1 fy1
    const __m128 nearZ = _mm_shuffle_ps(sz, sz, _MM_SHUFFLE(2, 2, 0, 0));   // nz0 nz0 nz1 nz1
    const __m128 farZ = _mm_shuffle_ps(sz, sz, _MM_SHUFFLE(3, 3, 1, 1));    // fz0 fz0 fz1 fz1
    __m128 tn = _mm_max_ps(nearXY, nearZ);
    __m128 tf = _mm_min_ps(farXY, farZ);
    tn = _mm_max_ps(_mm_max_ps(tn, _mm_shuffle_ps(tn, tn, kSwapPairs)), _mm_setzero_ps());  // n0 n0 n1 n1
    tf = _mm_min_ps(_mm_min_ps(tf, _mm_shuffle_ps(tf, tf, kSwapPairs)), _mm_set1_ps(tmax));
    const int mask = _mm_movemask_ps(_mm_cmple_ps(tn, _mm_mul_ps(tf, _mm_set1_ps(kFarScale))));
    alignas(16) float t[4];
    _mm_store_ps(t, tn);
    tEntry[0] = t[0];
    tEntry[1] = t[2];
    return (mask & 1) | ((mask >> 1) & 2);
}

// Walks one tree from root; leaf(link, count) intersects a leaf's contents, may lower tmax, and
// returns true to stop the walk (any-hit).
template <class LeafFn>
void walk(const std::vector<gpu::BvhNode>& nodes, std::uint32_t root, const NodeRay& ray, const float& tmax,
          LeafFn&& leaf) {
    struct Entry {
        std::uint32_t node;
        float t;
    };
    Entry stack[kStackSize];
    int sp = 0;
    std::uint32_t current = root;
    for (;;) {
        const gpu::BvhNode& node = nodes[current];
        float t[2];
        const int mask = slab2(node, ray, tmax, t);
        const bool hit[2] = {(mask & 1) != 0, (mask & 2) != 0};
        const int first = t[1] < t[0] ? 1 : 0;
        bool descend[2] = {false, false};
        for (int i = 0; i < 2; ++i) {
            const int k = i == 0 ? first : 1 - first;
            if (!hit[k]) continue;
            const std::uint32_t count = node.link[2 + k];
            if (count > 0) {
                if (leaf(node.link[k], count)) return;
            } else {
                descend[k] = node.link[k] != gpu::NODE_NONE;
            }
        }
        if (descend[0] && descend[1]) {
            const int far = 1 - first;
            stack[sp++] = {node.link[far], t[far]};
            current = node.link[first];
            continue;
        }
        if (descend[0] || descend[1]) {
            current = node.link[descend[0] ? 0 : 1];
            continue;
        }
        for (;;) {
            if (sp == 0) return;
            const Entry e = stack[--sp];
            if (e.t <= tmax) {
                current = e.node;
                break;
            }
        }
    }
}

// A primitive record against a ray in its object space.
inline bool intersectPrim(const gpu::Primitive& p, const WatertightRay& wr, const glm::vec3& o, const glm::vec3& d,
                          float tmax, PrimHit& hit) {
    const glm::vec3 a{bitsFloat(p.a.x), bitsFloat(p.a.y), bitsFloat(p.a.z)};
    const glm::vec3 b{bitsFloat(p.b.x), bitsFloat(p.b.y), bitsFloat(p.b.z)};
    switch (p.a.w & gpu::PRIM_KIND_MASK) {
    case gpu::PRIM_KIND_TRIANGLE: {
        const glm::vec3 c{bitsFloat(p.c.x), bitsFloat(p.c.y), bitsFloat(p.c.z)};
        return intersectTriangleInline(wr, a, b, c, tmax, hit);
    }
    case gpu::PRIM_KIND_SPHERE:
        return intersectSphereInline(o, d, a, b.x, tmax, hit);
    default:
        return intersectBoxInline(o, d, a, b, tmax, hit);
    }
}

// The ray enters object space in double and is rounded once: float dot products would lose
// digits to cancellation (a far origin against a large translation), and t inherits that error.
glm::vec3 transformPoint(const glm::vec4 rows[3], const glm::vec3& p) {
    const glm::dvec3 q(p);
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(glm::dot(glm::dvec3(glm::vec3(rows[i])), q) + rows[i].w);
    return out;
}
glm::vec3 transformVector(const glm::vec4 rows[3], const glm::vec3& v) {
    const glm::dvec3 q(v);
    glm::vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(glm::dot(glm::dvec3(glm::vec3(rows[i])), q));
    return out;
}

bool validRay(const Ray& ray) {
    const bool finite = std::isfinite(ray.origin.x) && std::isfinite(ray.origin.y) && std::isfinite(ray.origin.z) &&
                        std::isfinite(ray.dir.x) && std::isfinite(ray.dir.y) && std::isfinite(ray.dir.z);
    return finite && ray.dir != glm::vec3(0.0f) && ray.tmax > 0.0f;
}

template <bool AnyHit>
bool trace(const SceneBvh& bvh, const Ray& ray, Hit* out) {
    if (!validRay(ray) || bvh.nodes.empty()) return false;
    float tmax = ray.tmax;
    bool found = false;
    const NodeRay worldRay(ray.origin, ray.dir);
    walk(bvh.nodes, bvh.topRoot, worldRay, tmax, [&](std::uint32_t instanceIndex, std::uint32_t count) {
        for (std::uint32_t i = instanceIndex; i < instanceIndex + count; ++i) {
            const gpu::Instance& inst = bvh.instances[i];
            const glm::vec3 o = transformPoint(inst.worldToObject, ray.origin);
            const glm::vec3 d = transformVector(inst.worldToObject, ray.dir);
            const NodeRay objectRay(o, d);
            const WatertightRay wr(o, d);
            bool stop = false;
            walk(bvh.nodes, inst.info.x, objectRay, tmax, [&](std::uint32_t first, std::uint32_t n) {
                for (std::uint32_t p = first; p < first + n; ++p) {
                    PrimHit h;
                    if (!intersectPrim(bvh.prims[p], wr, o, d, tmax, h)) continue;
                    found = true;
                    if constexpr (AnyHit) {
                        stop = true;
                        return true;
                    } else {
                        tmax = h.t;
                        *out = {h.t, i, p, h.u, h.v, h.face};
                    }
                }
                return false;
            });
            if (stop) return true;
        }
        return false;
    });
    return found;
}

}  // namespace

bool intersectClosest(const SceneBvh& bvh, const Ray& ray, Hit& hit) { return trace<false>(bvh, ray, &hit); }

bool intersectAny(const SceneBvh& bvh, const Ray& ray) { return trace<true>(bvh, ray, nullptr); }

}  // namespace vkrt::bvh
