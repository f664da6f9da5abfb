// The recursion that gives a ray its radiance (docs/RENDERING.md §4-§6): closest hit, local
// shading with shadow rays, mirror/glossy reflection and dielectric reflection + refraction down
// to the maximum depth. One Integrator per thread: it owns that thread's ray counters.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "bvh.h"
#include "render_context.h"
#include "surface.h"

namespace vkrt::cpu {

struct RayCounts {
    std::uint64_t camera = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflection = 0;  // mirror and glossy reflections, dielectric reflections
    std::uint64_t refraction = 0;

    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        refraction += o.refraction;
        return *this;
    }
};

// The key of every random number drawn for one pixel sample (sampling.h).
struct SampleKey {
    std::uint32_t pixel = 0;   // j * width + i
    std::uint32_t sample = 0;  // s in [0, rpp)
    float time = 0.0f;         // the sample's time in the shutter: every ray of its tree has it
};

class Integrator {
public:
    explicit Integrator(const RenderContext& context) : ctx_(context) {}

    // The radiance of a camera ray (unit direction).
    glm::vec3 cameraRadiance(const bvh::Ray& ray, SampleKey key);

    const RayCounts& counts() const { return counts_; }

private:
    // `weight` is the product of the factors that will multiply this ray's radiance in the
    // pixel sample (m, F, 1-F, Beer, 1/g): branches below kMinBranchWeight are not traced.
    glm::vec3 trace(const bvh::Ray& ray, int depth, glm::vec3 weight, SampleKey key);
    glm::vec3 shade(const bvh::Ray& ray, const bvh::Hit& hit, int depth, glm::vec3 weight, SampleKey key);
    // Sum over lights (and light samples) of the shader's local term; shadowed unless CoolToWarm.
    glm::vec3 directLight(const Shader& shader, const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng,
                          const glm::vec3& view, const glm::vec3& kd, const glm::vec3& ks, int depth, SampleKey key);
    // The (possibly glossy) reflection seen from a surface with shading normal n and geometric normal ng
    // (both facing the incoming ray).
    glm::vec3 reflection(const bvh::Ray& ray, const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng,
                         float roughness, int depth, glm::vec3 weight, SampleKey key);
    glm::vec3 dielectric(const bvh::Ray& ray, const bvh::Hit& hit, const Shader& shader, const SurfacePoint& sp,
                         int depth, glm::vec3 weight, SampleKey key);
    bool occluded(const glm::vec3& origin, const glm::vec3& lightPoint, float time);

    const RenderContext& ctx_;
    RayCounts counts_;
};

}  // namespace vkrt::cpu
