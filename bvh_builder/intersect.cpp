#include "intersect_inline.h"

namespace vkrt::bvh {

namespace detail {

void edgeFunctionsDouble(float ax, float ay, float bx, float by, float cx, float cy, float& u, float& v, float& w) {
    u = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));
    v = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));
    w = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));
}

bool collinear(const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2) {
    const glm::dvec3 e1 = glm::dvec3(v1) - glm::dvec3(v0), e2 = glm::dvec3(v2) - glm::dvec3(v0);
    return glm::cross(e1, e2) == glm::dvec3(0.0);
}

}  // namespace detail

bool intersectTriangle(const WatertightRay& r, const glm::vec3& v0, const glm::vec3& v1, const glm::vec3& v2,
                       float tmax, PrimHit& hit) {
    return intersectTriangleInline(r, v0, v1, v2, tmax, hit);
}

bool intersectSphere(const glm::vec3& o, const glm::vec3& d, const glm::vec3& centre, float radius, float tmax,
                     PrimHit& hit) {
    return intersectSphereInline(o, d, centre, radius, tmax, hit);
}

bool intersectBox(const glm::vec3& o, const glm::vec3& d, const glm::vec3& lo, const glm::vec3& hi, float tmax,
                  PrimHit& hit) {
    return intersectBoxInline(o, d, lo, hi, tmax, hit);
}

}  // namespace vkrt::bvh
