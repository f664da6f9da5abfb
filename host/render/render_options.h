// What a render is asked to do, shared by the CPU reference and the GPU renderer so both
// compute the same image (docs/RENDERING.md).
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkrt {

struct Image;  // image.h

// Receives a progressive render's image after each pass but the last (RenderOptions::checkpoints).
class CheckpointSink {
public:
    virtual ~CheckpointSink() = default;
    virtual void checkpoint(const Image& soFar, int samplesDone) = 0;
};

// Values match gpu::SAMPLER_* in shaders/shared/device_host.h.
// Sobol2: two independently scrambled Sobol sequences interleaved (sampling.h sampleSeed), whose
// halves measure the error (adaptive sampling, docs/SAMPLING.md §7).
enum class SamplerKind : std::uint32_t { Jittered = 0, Regular = 1, Random = 2, Sobol = 3, Sobol2 = 4 };

std::string samplerName(SamplerKind sampler);  // "jittered", "regular", "random", "sobol", "sobol2"
// Throws std::invalid_argument naming the text when it is not a sampler's name.
SamplerKind parseSampler(const std::string& name);

// How a Diffuse surface's light from shape emitters and the environment map is estimated
// (docs/RENDERING.md §5); the image's expectation is the same for each. Values match
// gpu::ESTIMATOR_* in shaders/shared/device_host.h.
enum class Estimator : std::uint32_t { Bounce = 0, Nee = 1, MisBalance = 2, MisPower = 3 };

std::string estimatorName(Estimator estimator);  // "bounce", "nee", "mis-balance", "mis"
// Throws std::invalid_argument naming the text when it is not an estimator's name.
Estimator parseEstimator(const std::string& name);

struct RenderOptions {
    int width = 250;             // the instructor's reference renders are 250x250
    int height = 250;
    int samplesPerPixel = 16;    // rpp; n*n jitter when it is a square (references used ~16)
    int lightSamples = 1;        // area-light samples per pixel sample
    int glossSamples = 1;        // glossy directions per pixel sample
    int maxDepth = 4;            // reflection/refraction recursion (course default -k 4)
    std::uint32_t seed = 0;
    SamplerKind sampler = SamplerKind::Jittered;
    // Diffuse surfaces: how emitters and the environment map are found (a bounce ray, light
    // samples, or both weighted by multiple importance sampling). Scenes without Diffuse ignore it.
    Estimator estimator = Estimator::MisPower;
    std::optional<glm::vec3> background;  // overrides the scene's bgColor
    // false: rays that leave the scene see the background colour even when the scene has an
    // environment map, as in the course's own ray tracers (none sampled one) and its reference renders.
    bool environment = true;
    int camera = 0;              // index into Scene::cameras
    // Motion blur: the shutter's open and close in the instances' motion time (0: <transform>,
    // 1: <transformEnd>); absent, the whole motion [0, 1]. A scene without motion ignores it.
    std::optional<glm::vec2> shutter;
    // Render only rows [x, y) (0 = the top row); the others stay black. `--part I/N` sets it, and
    // `vkrt merge` puts the parts back together: every pixel is computed as in the whole image.
    std::optional<glm::ivec2> rows;
    // Progressive rendering (--progressive N): the samples are computed in `checkpoints` passes
    // (pass p ends after rpp * p / N samples of every pixel; the GPU rounds down to its dispatch
    // passes), and after each pass but the last `onCheckpoint` gets the image so far, the mean of
    // the samples computed, with how many. Every pixel still sums its samples in sample order, so
    // the returned image is bit-identical to a render without checkpoints. 0 or 1: no checkpoints.
    int checkpoints = 0;
    CheckpointSink* onCheckpoint = nullptr;  // not owned; null: no images before the end
    int threads = 0;             // CPU threads, 0 = all hardware threads
    bool quiet = false;          // -q: no progress bar, summary or warnings (errors are always printed)
    // Set asynchronously (Ctrl-C); renderers stop at the next tile or pass and throw RenderCancelled.
    const std::atomic<bool>* cancel = nullptr;
};

// The look of the instructor's reference renders (../shared/scenes/upstream/reference): a 50/255
// grey background whatever the scene's bgColor says, and no environment map (the course's code
// that made them never sampled one); their 250x250 at 16 jittered rpp are RenderOptions' defaults.
// `--look reference` applies it; an explicit --bg still wins (the command line applies it after).
inline constexpr float kReferenceLookBackground = 50.0f / 255.0f;
void applyReferenceLook(RenderOptions& options);

struct RenderCancelled {};

// Where the passes of a progressive render end, in `units` (samples on the CPU, dispatch passes on
// the GPU): units * p / checkpoints for p = 1..checkpoints, without repeats (more checkpoints than
// units give one pass per unit), the last one `units`. checkpoints <= 1: just {units}.
std::vector<int> checkpointEnds(int units, int checkpoints);

// The shutter a render uses (RenderOptions::shutter, or [0, 1]); throws std::invalid_argument
// naming both values when one is not finite or the shutter closes before it opens.
glm::vec2 shutterOf(const RenderOptions& options);

// The rows a render computes: RenderOptions::rows, or the whole image; throws std::invalid_argument
// naming them when they are not inside the image or empty.
glm::ivec2 rowsOf(const RenderOptions& options);

// Part `part` (1-based) of `parts` of an image `height` rows high: rows [height*(part-1)/parts,
// height*part/parts), so the parts tile the image exactly.
glm::ivec2 partRows(int height, int part, int parts);

}  // namespace vkrt
