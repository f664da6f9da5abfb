// CPU traversal of the two-level BVH: intersectClosest / intersectAny of bvh.h.
// Ordered depth-first traversal with a fixed-size stack: at each node both children's boxes are
// tested (one 64-byte node read), leaves are intersected at once, the nearer inner child is visited
// first and the farther one pushed with its entry distance, so it is skipped if a closer hit has
// been found by the time it is popped.
#include <cstring>

#include "bvh.h"
#include "intersect_inline.h"
#include "node_layout.h"

namespace vkrt::bvh {

namespace {

// Enough for any tree the builder makes: it bounds every level's depth by kMaxTreeDepth.
constexpr int kStackSize = 64;

// Slab test of both children of a node (Kay & Kajiya 1986, in the branch-free form of Williams et
// al. 2005: each axis's near plane is chosen by the sign of the direction, so an empty box, stored
// as lo = +FLT_MAX > hi = -FLT_MAX, always gives tNear > tFar). A zero direction component gives an
// infinite inverse; (plane - origin) * inf is NaN only when the origin lies on the plane, and the
// comparisons below are written so a NaN leaves the running interval unchanged (the ray then
// counts as inside that slab: conservative).
struct NodeRay {
    float o[3];
    float inv[3];
    int nearX, nearY, nearZ;  // 0: the near plane is lo, 1: it is hi

    NodeRay(const glm::vec3& origin, const glm::vec3& dir) {
        for (int i = 0; i < 3; ++i) {
            o[i] = origin[i];
            inv[i] = 1.0f / dir[i];
        }
        nearX = std::signbit(inv[0]) ? 1 : 0;
        nearY = std::signbit(inv[1]) ? 1 : 0;
        nearZ = std::signbit(inv[2]) ? 1 : 0;
    }
};

// Rounding in the slab test can shrink the interval by a few ulps and miss a primitive that
// touches its box's boundary; widening tFar by 1 + 2*gamma(3) makes the test conservative
// (Ize 2013, "Robust BVH Ray Traversal", JCGT 2(2)).
constexpr float kFarScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

inline bool slab(const float* f, int k, const NodeRay& r, float tmax, float& tEntry) {
    const float* xy = f + 4 * k;
    const float* z = f + 8 + 2 * k;
    float tn = 0.0f, tf = tmax;
    const float tx0 = (xy[r.nearX] - r.o[0]) * r.inv[0], tx1 = (xy[1 - r.nearX] - r.o[0]) * r.inv[0];
    const float ty0 = (xy[2 + r.nearY] - r.o[1]) * r.inv[1], ty1 = (xy[3 - r.nearY] - r.o[1]) * r.inv[1];
    const float tz0 = (z[r.nearZ] - r.o[2]) * r.inv[2], tz1 = (z[1 - r.nearZ] - r.o[2]) * r.inv[2];
    tn = tx0 > tn ? tx0 : tn;
    tn = ty0 > tn ? ty0 : tn;
    tn = tz0 > tn ? tz0 : tn;
    tf = tx1 < tf ? tx1 : tf;
    tf = ty1 < tf ? ty1 : tf;
    tf = tz1 < tf ? tz1 : tf;
    tEntry = tn;
    return tn <= tf * kFarScale;
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
        float f[12];
        std::memcpy(f, &node, sizeof f);
        float t[2];
        const bool hit[2] = {slab(f, 0, ray, tmax, t[0]), slab(f, 1, ray, tmax, t[1])};
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
