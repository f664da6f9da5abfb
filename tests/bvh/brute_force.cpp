#include "brute_force.h"

#include <algorithm>

#include "hit_order.h"
#include "intersect.h"

namespace vkrt::bvh::test {

namespace {

struct ObjectRay {
    glm::vec3 o, d;
    WatertightRay wr;
};

ObjectRay toObject(const gpu::Instance& inst, const Ray& ray) {
    glm::dmat4 inv(1.0);  // column-major from the rows
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) inv[c][r] = inst.worldToObject[r][c];
    const glm::vec3 o(inv * glm::dvec4(ray.origin, 1.0));
    const glm::vec3 d(inv * glm::dvec4(ray.dir, 0.0));
    return {o, d, WatertightRay(o, d)};
}

bool hitPrim(const PrimitiveInput& p, const ObjectRay& r, float tmax, float& t) {
    PrimHit h;
    bool hit = false;
    switch (p.kind) {
    case gpu::PRIM_KIND_TRIANGLE: hit = intersectTriangle(r.wr, p.a, p.b, p.c, tmax, h); break;
    case gpu::PRIM_KIND_SPHERE: hit = intersectSphere(r.o, r.d, p.a, p.b.x, tmax, h); break;
    default: hit = intersectBox(r.o, r.d, p.a, p.b, tmax, h); break;
    }
    if (hit) t = h.t;
    return hit;
}

}  // namespace

FlatIndex flatIndexOf(const SceneBvh& bvh) {
    FlatIndex flat(bvh.groups.size());
    for (std::size_t g = 0; g < bvh.groups.size(); ++g) {
        const GroupRange& range = bvh.groups[g];
        flat[g].resize(range.primCount);
        for (std::uint32_t k = range.firstPrim; k < range.firstPrim + range.primCount; ++k) flat[g][bvh.primSource[k]] = k;
    }
    return flat;
}

bool bruteClosest(const TestScene& scene, const Rows& rows, const FlatIndex& flat, const Ray& ray, BruteHit& hit) {
    float limit = ray.tmax;
    bool found = false;
    std::uint32_t bestFlat = 0;
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
        const ObjectRay r = toObject(rows[i], ray);
        const std::uint32_t group = scene.instances[i].group;
        const auto& prims = scene.groups[group];
        for (std::uint32_t p = 0; p < prims.size(); ++p) {
            float t;
            if (!hitPrim(prims[p], r, limit, t)) continue;
            const std::uint32_t f = flat[group][p];
            if (found && !gpu::hitWins(t, i, f, hit.t, hit.instance, bestFlat)) continue;
            hit = {t, i, p};
            bestFlat = f;
            found = true;
            limit = std::min(gpu::hitBucketLimit(t), ray.tmax);
        }
    }
    return found;
}

bool bruteAny(const TestScene& scene, const Rows& rows, const Ray& ray) {
    for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
        const ObjectRay r = toObject(rows[i], ray);
        for (const PrimitiveInput& p : scene.groups[scene.instances[i].group]) {
            float t;
            if (hitPrim(p, r, ray.tmax, t)) return true;
        }
    }
    return false;
}

bool bruteOne(const TestScene& scene, const Rows& rows, std::uint32_t instance, std::uint32_t sourcePrim,
              const Ray& ray, float& t) {
    const ObjectRay r = toObject(rows[instance], ray);
    return hitPrim(scene.groups[scene.instances[instance].group][sourcePrim], r, ray.tmax, t);
}

}  // namespace vkrt::bvh::test
