// The converged reference a sweep measures error against: rendered once at a high rpp and cached on
// disk, keyed by a hash of the scene file's text and of every option that changes the image.
//
// Cache: <cacheDir>/references/<key>.exr (the reference), <key>_noise.exr (its own estimated
// variance per pixel and channel), <key>_masks_v<N>.png (region_masks.h; recomputed alone when
// missing) and <key>.txt (what was rendered, how long it took). defaultCacheDir() is
// $XDG_CACHE_HOME/vkrt, else ~/.cache/vkrt.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>

#include "image.h"
#include "region_masks.h"
#include "render_options.h"
#include "scene.h"
#include "study_renderer.h"

namespace vkrt::study {

// The reference is the mean of two renders with these seeds (rpp/2 each): the difference of the
// halves estimates the reference's own noise. Sweeps must not use them (their samples would be
// correlated with the reference's).
inline constexpr std::uint32_t kReferenceSeedA = 0x9e3779b9u;
inline constexpr std::uint32_t kReferenceSeedB = 0x7f4a7c15u;

// The reference's estimator (render_options.h). Every estimator has the same expectation (docs/
// RENDERING.md §5), so the reference serves a sweep of any of them and the cache key leaves the
// estimator out; it is rendered with MIS (power heuristic), which never does worse than the others
// by much and far better where small emitters light Diffuse surfaces (docs/SAMPLING.md §4).
inline constexpr Estimator kReferenceEstimator = Estimator::MisPower;

struct ReferenceSpec {
    // Size, depth, light/gloss samples, background, camera, threads. The estimator is ignored: the
    // reference always uses kReferenceEstimator.
    RenderOptions options;
    int rpp = 4096;
    SamplerKind sampler = SamplerKind::Sobol;
    Device device = Device::Gpu;
    // The rendered camera's thin lens (focus distance, aperture): the command line may override
    // the scene file's, so the file's text alone does not say it.
    glm::vec2 lens{0.0f};
};

struct Reference {
    Image image;
    Image noise;          // estimated variance of `image` per pixel and channel: (A - B)^2 / 4
    RegionMasks masks;
    std::string key;      // 16 hex digits
    std::filesystem::path imagePath;
    bool fromCache = false;
    double seconds = 0.0; // time to render it (when it was rendered)
};

std::filesystem::path defaultCacheDir();

// The cache key: XXH64 of the scene text and a canonical description of spec.
std::string referenceKey(const std::string& sceneText, const ReferenceSpec& spec);

// Renders one of the reference's two halves (the options say its seed and rpp); by default
// renderer.render on spec.device, and under MPI shared among the ranks (sweep.cpp).
using HalfRenderer = std::function<TimedRender(const RenderOptions& half)>;

// Loads the cached reference, or renders (and caches) it; progress lines go to `log`.
Reference loadOrRenderReference(StudyRenderer& renderer, const PreparedScene& scene,
                                const std::string& sceneText, const ReferenceSpec& spec,
                                const std::filesystem::path& cacheDir, std::ostream& log,
                                const HalfRenderer& renderHalf = {});

}  // namespace vkrt::study
