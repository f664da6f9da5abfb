// CPU traversal of the two-level BVH: intersectClosest / intersectAny of bvh.h.
// Ordered depth-first traversal of the 8-wide copy of the trees (SceneBvh::cpu, wide_bvh.h) with a
// fixed-size stack: at each node the 8 children's boxes are tested at once, leaves are intersected
// at once, the nearest inner child is visited next and the others pushed with their entry
// distance, so they are skipped if a closer hit has been found by the time they are popped.
#include <immintrin.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "bvh.h"
#include "hit_order.h"
#include "intersect_inline.h"
#include "node_layout.h"
#include "triangle_groups.h"
#include "wide_slab.h"

namespace vkrt::bvh {

namespace {

// Walks one 8-wide tree from root; leaf(link, count) intersects a leaf's contents, may lower tmax,
// and returns true to stop the walk (any-hit). Hit inner children are visited nearest first; the
// others wait on the stack with their entry distance and are dropped if a closer hit came first.
template <class LeafFn>
void walk(const std::vector<WideNode>& nodes, std::uint32_t root, const NodeRay& ray, const float& tmax,
          LeafFn&& leaf) {
    struct Entry {
        std::uint32_t node;
        float t;
    };
    Entry stack[kWideStackSize];
    int sp = 0;
    std::uint32_t current = root;
    for (;;) {
        const WideNode& node = nodes[current];
        alignas(32) float t[kWideWidth];
        int mask = slabs(node, ray, tmax, t);
        Entry inner[kWideWidth];
        int innerCount = 0;
        while (mask) {
            const int k = std::countr_zero(static_cast<unsigned>(mask));
            mask &= mask - 1;
            if (node.count[k] > 0) {
                if (leaf(node.link[k], node.count[k])) return;
            } else if (node.link[k] != NODE_NONE) {
                inner[innerCount++] = {node.link[k], t[k]};
            }
        }
        // Nearest first: sort the (at most kWideWidth) entries by distance, push all but the nearest.
        for (int i = 1; i < innerCount; ++i)
            for (int j = i; j > 0 && inner[j].t < inner[j - 1].t; --j) std::swap(inner[j], inner[j - 1]);
        int next = -1;
        for (int i = innerCount - 1; i >= 0; --i) {
            if (inner[i].t > tmax) continue;  // a leaf of this node already hit closer
            if (next >= 0) stack[sp++] = inner[next];
            next = i;
        }
        if (next >= 0) {
            current = inner[next].node;
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
    switch (gpu::primitiveKind(p.a)) {
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

// A leaf of triangle groups (triangle_groups.h) against the ray: the watertight test's edge
// functions for four triangles per instruction, the same float operations in the same order as
// intersectTriangleInline, so each lane's u, v, w are its scalar test's bit for bit; a lane whose
// edge function is exactly 0 is redone by the scalar's double fallback. The lanes left are
// finished one by one in primitive order by the scalar test's own tail (watertightDistance) with
// the tmax of that moment, as the one-at-a-time loop would. accept(prim, hit) returns true to
// stop (any-hit); the leaf's primitives are [first, first + 4 * groups), padding lanes excluded.
template <class Accept>
bool triangleLeaf(const TriangleGroup* group, std::uint32_t groups, std::uint32_t first, const WatertightRay& r,
                  const float& tmax, Accept&& accept) {
    const __m128 sx = _mm_set1_ps(r.sx), sy = _mm_set1_ps(r.sy), sz = _mm_set1_ps(r.sz), zero = _mm_setzero_ps();
    const __m128 ox = _mm_set1_ps(r.org[r.kx]), oy = _mm_set1_ps(r.org[r.ky]), oz = _mm_set1_ps(r.org[r.kz]);
    for (const TriangleGroup* g = group; g != group + groups; ++g) {
        // Corner c relative to the origin, sheared: (x - sx z, y - sy z) and sz z.
        __m128 x[3], y[3], z[3];
        for (int c = 0; c < 3; ++c) {
            const __m128 cz = _mm_sub_ps(_mm_load_ps(g->corner[c][r.kz]), oz);
            x[c] = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(g->corner[c][r.kx]), ox), _mm_mul_ps(sx, cz));
            y[c] = _mm_sub_ps(_mm_sub_ps(_mm_load_ps(g->corner[c][r.ky]), oy), _mm_mul_ps(sy, cz));
            z[c] = _mm_mul_ps(sz, cz);
        }
        const __m128 u = _mm_sub_ps(_mm_mul_ps(x[2], y[1]), _mm_mul_ps(y[2], x[1]));
        const __m128 v = _mm_sub_ps(_mm_mul_ps(x[0], y[2]), _mm_mul_ps(y[0], x[2]));
        const __m128 w = _mm_sub_ps(_mm_mul_ps(x[1], y[0]), _mm_mul_ps(y[1], x[0]));
        // Lanes that can still hit: no two edge functions of opposite signs, and not padding or
        // collinear. Redoing an exact zero in double cannot save a lane dropped here: rounding is
        // monotonic, so a nonzero float difference of products has its exact value's sign.
        const __m128 negative = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(u, zero), _mm_cmplt_ps(v, zero)), _mm_cmplt_ps(w, zero));
        const __m128 positive = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(u, zero), _mm_cmpgt_ps(v, zero)), _mm_cmpgt_ps(w, zero));
        int lanes = static_cast<int>(g->lanes) & ~_mm_movemask_ps(_mm_and_ps(negative, positive));
        if (!lanes) continue;
        alignas(16) float U[4], V[4], W[4], X[3][4], Y[3][4], Z[3][4];
        _mm_store_ps(U, u), _mm_store_ps(V, v), _mm_store_ps(W, w);
        for (int c = 0; c < 3; ++c) _mm_store_ps(X[c], x[c]), _mm_store_ps(Y[c], y[c]), _mm_store_ps(Z[c], z[c]);
        while (lanes) {
            const int k = std::countr_zero(static_cast<unsigned>(lanes));
            lanes &= lanes - 1;
            if (U[k] == 0.0f || V[k] == 0.0f || W[k] == 0.0f)
                detail::edgeFunctionsDouble(X[0][k], Y[0][k], X[1][k], Y[1][k], X[2][k], Y[2][k], U[k], V[k], W[k]);
            PrimHit h;
            const auto prim = first + 4u * static_cast<std::uint32_t>(g - group) + static_cast<std::uint32_t>(k);
            if (watertightDistance(U[k], V[k], W[k], Z[0][k], Z[1][k], Z[2][k], tmax, h) && accept(prim, h)) return true;
        }
    }
    return false;
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
    if (bvh.cpu.nodes.empty()) {
        // A default-constructed SceneBvh has no nodes at all and simply has no hits.
        if (!bvh.cpu.built && !bvh.nodes.empty())
            throw std::logic_error("bvh: CPU traversal of a BVH built with BuildOptions::cpuTraversal = false");
        return false;
    }
    if (!validRay(ray)) return false;
    float tmax = ray.tmax;
    bool found = false;
    const NodeRay worldRay(ray.origin, ray.dir);
    const auto instances = [&](std::uint32_t instanceIndex, std::uint32_t count) {
        for (std::uint32_t i = instanceIndex; i < instanceIndex + count; ++i) {
            // An identity instance never moves (wide_bvh.h): no pose to look up.
            const bool identity = bvh.cpu.identity[i] != 0;
            gpu::Instance posed;
            const gpu::Instance& inst = identity ? bvh.instances[i] : instanceAtTime(bvh, i, ray.time, posed);
            const glm::vec3 o = identity ? ray.origin : transformPoint(inst.worldToObject, ray.origin);
            const glm::vec3 d = identity ? ray.dir : transformVector(inst.worldToObject, ray.dir);
            const NodeRay objectRay = identity ? worldRay : NodeRay(o, d);
            const WatertightRay wr(o, d);
            bool stop = false;
            // A primitive's hit: true ends the walk (any-hit).
            const auto accept = [&](std::uint32_t p, const PrimHit& h) {
                if constexpr (AnyHit) {
                    found = stop = true;
                    return true;
                } else {
                    // The kernels' rule for hits whose distances differ by rounding only
                    // (shaders/shared/hit_order.h); tmax becomes the end of the best's bucket.
                    if (found && !gpu::hitWins(h.t, i, p, out->t, out->instance, out->prim)) return false;
                    found = true;
                    tmax = std::min(gpu::hitBucketLimit(h.t), ray.tmax);
                    *out = {h.t, i, p, h.u, h.v, h.face};
                    return false;
                }
            };
            walk(bvh.cpu.nodes, bvh.cpu.groupRoots[gpu::instanceGroup(inst.info)], objectRay, tmax, [&](std::uint32_t first, std::uint32_t n) {
                const std::uint32_t group = bvh.cpu.triangles.leafGroup[first];
                if (group != TriangleGroups::kNone)
                    return triangleLeaf(&bvh.cpu.triangles.groups[group], (n + 3) / 4, first, wr, tmax, accept);
                for (std::uint32_t p = first; p < first + n; ++p) {
                    PrimHit h;
                    if (intersectPrim(bvh.prims[p], wr, o, d, tmax, h) && accept(p, h)) return true;
                }
                return false;
            });
            if (stop) return true;
        }
        return false;
    };
    // A scene of one still, untransformed instance (no instancing in the file): its group's walk
    // alone. The top level's one box culls nothing the group's root boxes do not, and skipping it
    // saves a node visit per ray: in a small scene (a Cornell box) a ray visits ~1.2 nodes of its group.
    if (bvh.cpu.identity.size() == 1 && bvh.cpu.identity[0] != 0) {
        instances(0, 1);
        return found;
    }
    walk(bvh.cpu.nodes, bvh.cpu.topRoot, worldRay, tmax, instances);
    return found;
}

}  // namespace

bool intersectClosest(const SceneBvh& bvh, const Ray& ray, Hit& hit) { return trace<false>(bvh, ray, &hit); }

bool intersectAny(const SceneBvh& bvh, const Ray& ray) { return trace<true>(bvh, ray, nullptr); }

}  // namespace vkrt::bvh
