// The Embree peer's camera rule and ray streams (../shared/peer/README.md), shared by `vkrt-bench
// bvh` (which traces each ray as it makes it, as the peer does) and `vkrt-bench gpu` (which makes
// them all first, since the device takes them as one array), so both measure the peer's rays.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <random>

#include <glm/glm.hpp>

#include "bench_mesh.h"
#include "bvh.h"

namespace vkrt::bench {

// Scaling by the reciprocal length (not dividing) matches the peer's rounding.
inline glm::vec3 normalised(const glm::vec3& v) { return v * (1.0f / std::sqrt(glm::dot(v, v))); }

struct PeerCamera {
    glm::vec3 centre, eye, fwd, right, up, light;
    float radius;
    // The image plane's half extent at distance 1: the peer's 0.8, or 0.8 / zoom (`vkrt-bench gpu
    // rays --zoom`, so that a mesh fills the frame: at 0.8 ~90% of the dragon's rays miss).
    float halfExtent = 0.8f;
    explicit PeerCamera(const BenchMesh& m);
};

// Row y of a W x H x SPP image: calls f(k, ray) for every primary ray of the row, k = (y*W + x)*SPP + s,
// with the peer's jitter stream (std::mt19937 seeded with y, two draws per ray).
template <class F>
void forEachPrimaryRay(const PeerCamera& cam, int w, int h, int spp, int y, F&& f) {
    std::mt19937 rng(y);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int x = 0; x < w; ++x)
        for (int s = 0; s < spp; ++s) {
            const std::size_t k = (static_cast<std::size_t>(y) * w + x) * spp + s;
            const float px = (x + u(rng)) / w * 2 - 1;
            const float py = 1 - (y + u(rng)) / h * 2;
            const glm::vec3 d = normalised(cam.fwd + cam.right * (px * cam.halfExtent) + cam.up * (py * cam.halfExtent));
            f(k, bvh::Ray{cam.eye, d, 1e30f});
        }
}

// The hit triangle's geometric normal, turned to face the ray (the peer's Ng rule).
glm::vec3 facingNormal(const gpu::Primitive& triangle, const glm::vec3& dir);

// From a primary hit point p with facing normal n: the occlusion ray to the light (tmax = distance).
bvh::Ray shadowRay(const PeerCamera& cam, const glm::vec3& p, const glm::vec3& n);

// The diffuse rays of one image row, in order: one cosine-weighted direction per primary hit,
// from the peer's stream for that row (std::mt19937 seeded with 1000 + y).
class DiffuseRow {
public:
    explicit DiffuseRow(int y) : rng_(1000 + y) {}
    bvh::Ray next(const PeerCamera& cam, const glm::vec3& p, const glm::vec3& n);

private:
    std::mt19937 rng_;
    std::uniform_real_distribution<float> u_{0.0f, 1.0f};
};

}  // namespace vkrt::bench
