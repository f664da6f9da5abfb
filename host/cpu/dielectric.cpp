#include "dielectric.h"

#include <cmath>

namespace vkrt::cpu {

float fresnelDielectric(float cosIncident, float n1, float n2) {
    // Equal indices are an invisible interface; rounding in the general formula would leave ~1e-8.
    if (n1 == n2) return 0.0f;
    const float cosI = glm::clamp(cosIncident, 0.0f, 1.0f);
    const float ratio = n1 / n2;
    const float sin2T = ratio * ratio * (1.0f - cosI * cosI);
    if (sin2T >= 1.0f) return 1.0f;
    const float cosT = std::sqrt(1.0f - sin2T);
    const float rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    const float rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
    return 0.5f * (rs * rs + rp * rp);
}

glm::vec3 refractDirection(const glm::vec3& d, const glm::vec3& n, float n1, float n2) {
    if (n1 == n2) return d;
    const float cosI = glm::clamp(-glm::dot(d, n), 0.0f, 1.0f);
    const float ratio = n1 / n2;
    const float sin2T = ratio * ratio * (1.0f - cosI * cosI);
    const float cosT = std::sqrt(glm::max(0.0f, 1.0f - sin2T));
    return glm::normalize(ratio * d + (ratio * cosI - cosT) * n);
}

glm::vec3 beerLambert(const glm::vec3& perUnit, float distance) {
    return {std::pow(perUnit.x, distance), std::pow(perUnit.y, distance), std::pow(perUnit.z, distance)};
}

}  // namespace vkrt::cpu
