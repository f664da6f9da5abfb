#include "shading.h"

#include <algorithm>
#include <cmath>

namespace vkrt::cpu {

glm::vec3 lambertian(const glm::vec3& kd, const glm::vec3& intensity, const glm::vec3& n, const glm::vec3& l) {
    return kd * intensity * glm::max(0.0f, glm::dot(n, l));
}

glm::vec3 blinnPhongSpecular(const glm::vec3& ks, float phongExp, const glm::vec3& intensity, const glm::vec3& n,
                             const glm::vec3& l, const glm::vec3& v) {
    const glm::vec3 sum = l + v;
    const float len2 = glm::dot(sum, sum);
    // L = -V has no half vector (only possible with a bent shading normal): no highlight.
    if (!(len2 > 0.0f)) return glm::vec3(0.0f);
    const float nh = glm::max(0.0f, glm::dot(n, glm::normalize(sum)));
    // pow(0, 0) is undefined in GLSL; the spec defines the exponent-0 highlight as 1 everywhere.
    const float highlight = phongExp == 0.0f ? 1.0f : std::pow(nh, phongExp);
    return ks * intensity * highlight;
}

glm::vec3 coolToWarm(const glm::vec3& kd, const glm::vec3& intensity, const glm::vec3& n, const glm::vec3& l) {
    const glm::vec3 kcool = glm::vec3(0.0f, 0.0f, 0.4f) + 0.2f * kd;
    const glm::vec3 kwarm = glm::vec3(0.4f, 0.4f, 0.0f) + 0.6f * kd;
    const float t = (1.0f + glm::dot(n, l)) * 0.5f;
    return intensity * (t * kwarm + (1.0f - t) * kcool);
}

glm::vec3 mirrorDirection(const glm::vec3& d, const glm::vec3& n) { return d - 2.0f * glm::dot(d, n) * n; }

glm::vec3 glossyDirection(const glm::vec3& r, float roughness, glm::vec2 sample) {
    if (roughness == 0.0f) return r;
    const glm::vec3 ar = glm::abs(r);
    // The axis least aligned with r (ties: x before y before z) is never parallel to it.
    glm::vec3 axis(0.0f);
    if (ar.x <= ar.y && ar.x <= ar.z) axis.x = 1.0f;
    else if (ar.y <= ar.z) axis.y = 1.0f;
    else axis.z = 1.0f;
    const glm::vec3 u = glm::normalize(glm::cross(r, axis));
    const glm::vec3 v = glm::cross(r, u);
    if (roughness > 1.0f) {
        // The same direction divided by the roughness: r + a*(..) overflowed float's squared length
        // for a > ~1e19 and normalised to a zero vector (every sample black). The sum is then
        // rescaled by its largest component, since r / a alone can be tiny (a sample at the centre).
        const glm::vec3 w = r / roughness + (sample.x - 0.5f) * u + (sample.y - 0.5f) * v;
        const float m = std::max(std::fabs(w.x), std::max(std::fabs(w.y), std::fabs(w.z)));
        return m > 0.0f ? glm::normalize(w / m) : r;
    }
    return glm::normalize(r + roughness * (sample.x - 0.5f) * u + roughness * (sample.y - 0.5f) * v);
}

}  // namespace vkrt::cpu
