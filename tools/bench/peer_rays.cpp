#include "peer_rays.h"

namespace vkrt::bench {

PeerCamera::PeerCamera(const BenchMesh& m) {
    centre = (m.lo + m.hi) * 0.5f;
    const glm::vec3 ext = m.hi - m.lo;
    radius = 0.5f * std::sqrt(glm::dot(ext, ext));
    eye = centre + normalised(glm::vec3(0.6f, 0.4f, 1.0f)) * (1.5f * radius);
    fwd = normalised(centre - eye);
    right = normalised(glm::cross(fwd, glm::vec3(0.0f, 1.0f, 0.0f)));
    up = glm::cross(right, fwd);
    light = centre + glm::vec3(radius * 2.0f, radius * 3.0f, radius * 2.0f);
}

namespace {

glm::vec3 vertex(const glm::uvec4& u) {
    return glm::vec3(std::bit_cast<float>(u.x), std::bit_cast<float>(u.y), std::bit_cast<float>(u.z));
}

// 1e-4 r along the normal, as the peer offsets both secondary ray kinds.
glm::vec3 offsetOrigin(const PeerCamera& cam, const glm::vec3& p, const glm::vec3& n) {
    return p + n * static_cast<float>(1e-4 * cam.radius);
}

}  // namespace

glm::vec3 facingNormal(const gpu::Primitive& triangle, const glm::vec3& dir) {
    const glm::vec3 v0 = vertex(triangle.a);
    const glm::vec3 ng = normalised(glm::cross(vertex(triangle.b) - v0, vertex(triangle.c) - v0));
    return glm::dot(ng, dir) > 0.0f ? -ng : ng;
}

bvh::Ray shadowRay(const PeerCamera& cam, const glm::vec3& p, const glm::vec3& n) {
    const glm::vec3 o = offsetOrigin(cam, p, n);
    glm::vec3 d = cam.light - o;
    const float len = std::sqrt(glm::dot(d, d));
    d = d * (1 / len);
    return bvh::Ray{o, d, len};
}

bvh::Ray DiffuseRow::next(const PeerCamera& cam, const glm::vec3& p, const glm::vec3& n) {
    const glm::vec3 axis = std::fabs(n.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 t = normalised(glm::cross(axis, n)), b = glm::cross(n, t);
    const float r1 = u_(rng_), r2 = u_(rng_), sr = std::sqrt(r1);
    const float ph = static_cast<float>(2 * M_PI * r2);
    const glm::vec3 d = normalised(t * (sr * std::cos(ph)) + b * (sr * std::sin(ph)) + n * std::sqrt(1 - r1));
    return bvh::Ray{offsetOrigin(cam, p, n), d, 1e30f};
}

}  // namespace vkrt::bench
