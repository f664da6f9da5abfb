// The recursion that gives a ray its radiance (docs/RENDERING.md §4-§6): closest hit, local
// shading with shadow rays, mirror/glossy reflection, dielectric reflection + refraction and the
// Diffuse bounce down to the maximum depth; shape emitters seen or sampled, the environment for
// rays that leave. One Integrator per thread: it owns that thread's ray counters.
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
    std::uint64_t bounce = 0;      // Diffuse bounces

    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        refraction += o.refraction;
        bounce += o.bounce;
        return *this;
    }
};

// The key of every random number drawn for one pixel sample (sampling.h).
struct SampleKey {
    std::uint32_t pixel = 0;   // j * width + i
    std::uint32_t sample = 0;  // the sample's index in its sequence: s in [0, rpp), sobol2's s / 2 (sampling.h)
    std::uint32_t seed = 0;    // the render's seed, or sobol2's seed of sample s (sampleSeed)
    float time = 0.0f;         // the sample's time in the shutter: every ray of its tree has it
};

class Integrator {
public:
    explicit Integrator(const RenderContext& context);

    // The radiance of a camera ray (unit direction).
    glm::vec3 cameraRadiance(const bvh::Ray& ray, SampleKey key);

    const RayCounts& counts() const { return counts_; }

private:
    // `weight` is the product of the factors that will multiply this ray's radiance in the
    // pixel sample (m, F, 1-F, Beer, 1/g, kd): branches below kMinBranchWeight are not traced.
    // `bouncePdf` > 0: the ray is a Diffuse bounce with that cosine density, whose surface's light
    // samples already looked for emitters and the environment (the estimator weighs the two).
    glm::vec3 trace(const bvh::Ray& ray, int depth, glm::vec3 weight, SampleKey key, float bouncePdf = 0.0f);
    glm::vec3 shade(const bvh::Ray& ray, const bvh::Hit& hit, int depth, glm::vec3 weight, SampleKey key, float bouncePdf);
    // Sum over lights (and light samples) of the shader's local term; shadowed unless CoolToWarm.
    // Shape emitters count as every shader's lights; on a Diffuse surface (`bounces`) they are
    // sampled only as the estimator says, weighted against the bounce.
    glm::vec3 directLight(const Shader& shader, const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng,
                          const glm::vec3& view, const glm::vec3& kd, const glm::vec3& ks, int depth, SampleKey key);
    // The course's Diffuse: kd times the light arriving over the cosine-weighted hemisphere, one
    // bounce ray per pixel sample, plus its light samples; black at the maximum depth.
    glm::vec3 diffuse(const Shader& shader, const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng,
                      const glm::vec3& kd, int depth, glm::vec3 weight, SampleKey key);
    // The radiance an emitter's surface sends along `ray` (which hit it at sp), weighted against
    // the light samples of the Diffuse surface the ray left, if it left one.
    glm::vec3 emitted(const bvh::Ray& ray, const SurfacePoint& sp, float bouncePdf) const;
    // What a ray that leaves the scene along dir sees: the environment map (weighted against the
    // light samples of the Diffuse surface it left, if it left one that took them) or the background.
    glm::vec3 escaped(const glm::vec3& dir, float bouncePdf) const;
    // A Diffuse surface's k light samples of the environment map, drawn by luminance.
    glm::vec3 environmentLight(const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng, int depth, SampleKey key);
    // The (possibly glossy) reflection seen from a surface with shading normal n and geometric normal ng
    // (both facing the incoming ray).
    glm::vec3 reflection(const bvh::Ray& ray, const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng,
                         float roughness, int depth, glm::vec3 weight, SampleKey key);
    glm::vec3 dielectric(const bvh::Ray& ray, const bvh::Hit& hit, const Shader& shader, const SurfacePoint& sp,
                         int depth, glm::vec3 weight, SampleKey key);
    bool occluded(const glm::vec3& origin, const glm::vec3& lightPoint, float time);
    // The first light sample a hit at `depth` takes, drawn before the ray that finds the hit is
    // traced: a Sobol sample is a chain of dependent multiplies whose latency the shadow ray
    // would otherwise wait for, and the traversal hides it. directLight takes it from here when it
    // draws that sample for the same pixel sample and depth.
    struct EarlyLightSample {
        std::uint32_t pixel = 0, sample = 0, seed = 0;
        int depth = -1;
        glm::vec2 area{0.0f};       // the first area light's sample 0
        std::uint32_t emitter = 0;  // the shape emitter light sample 0 goes to, and its sample
        glm::vec2 emitterSample{0.0f};
    };
    void drawEarlyLightSample(int depth, SampleKey key);
    bool hasEarlyLightSample(int depth, SampleKey key) const {
        return early_.depth == depth && early_.pixel == key.pixel && early_.sample == key.sample && early_.seed == key.seed;
    }
    std::uint32_t pickEmitterFor(int depth, SampleKey key, std::uint32_t index) const;
    // Light sample `index` of a hit at `depth` for the light of ordinal `ordinal` (an area light's
    // areaOrdinal, an emitter's emitterLightOrdinal): RENDERING.md §2's dimension dimLight.
    glm::vec2 lightSample(int depth, SampleKey key, std::uint32_t index, std::uint32_t ordinal) const;
    // Whether a Diffuse surface samples emitters and the environment (every estimator but the
    // plain bounce), and whether it weighs those samples against its bounce (MIS).
    bool diffuseSamplesLights() const { return ctx_.estimator != Estimator::Bounce; }
    bool diffuseWeighs() const { return ctx_.estimator == Estimator::MisBalance || ctx_.estimator == Estimator::MisPower; }

    const RenderContext& ctx_;
    bool hasAreaLights_ = false;
    EarlyLightSample early_;
    RayCounts counts_;
};

}  // namespace vkrt::cpu
