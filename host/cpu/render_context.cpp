#include "render_context.h"

#include <stdexcept>
#include <string>

#include "sampling.h"
#include "used_shaders.h"

namespace vkrt::cpu {

namespace {

void requireAtLeast(const char* what, long long value, long long minimum) {
    if (value < minimum)
        throw std::invalid_argument(std::string("render options: ") + what + " = " + std::to_string(value) +
                                    " (must be at least " + std::to_string(minimum) + ")");
}

}  // namespace

RenderContext makeRenderContext(const Scene& scene, const SceneAccel& accel, const RenderOptions& options) {
    requireAtLeast("width", options.width, 1);
    requireAtLeast("height", options.height, 1);
    requireAtLeast("samples per pixel", options.samplesPerPixel, 1);
    requireAtLeast("light samples", options.lightSamples, 1);
    requireAtLeast("gloss samples", options.glossSamples, 1);
    requireAtLeast("max depth", options.maxDepth, 0);
    // Sample indices s*k + j and pixel indices j*width + i are 32-bit on the GPU.
    const long long lightCount = static_cast<long long>(options.samplesPerPixel) * options.lightSamples;
    const long long glossCount = static_cast<long long>(options.samplesPerPixel) * options.glossSamples;
    const long long pixelCount = static_cast<long long>(options.width) * options.height;
    if (lightCount > 0xffffffffLL || glossCount > 0xffffffffLL || pixelCount > 0xffffffffLL)
        throw std::invalid_argument("render options: image size or sample counts exceed 2^32");
    if (scene.cameras.empty()) throw std::invalid_argument(scene.path + ": the scene has no camera");
    if (options.camera < 0 || options.camera >= static_cast<int>(scene.cameras.size()))
        throw std::invalid_argument("render options: camera " + std::to_string(options.camera) + " does not exist (" +
                                    std::to_string(scene.cameras.size()) + " in " + scene.path + ")");

    RenderContext ctx;
    ctx.scene = &scene;
    ctx.accel = &accel;
    ctx.camera = makeCameraFrame(scene.cameras[options.camera], options.width, options.height);
    ctx.lights = makeLightSources(scene);
    ctx.lighting = accel.lighting ? accel.lighting : std::make_shared<const SceneLighting>(buildSceneLighting(scene));
    ctx.environment = options.environment && ctx.lighting->environment.faceSize > 0;
    ctx.estimator = options.estimator;
    ctx.background = options.background ? *options.background : scene.background;
    ctx.sampler = static_cast<unsigned>(options.sampler);
    ctx.seed = options.seed;
    ctx.maxDepth = options.maxDepth;
    ctx.finalRays = finalRays(scene, options);
    ctx.dielectricOneBranch = pathTraced(scene);
    ctx.samplesPerPixel = static_cast<unsigned>(options.samplesPerPixel);
    ctx.lightSamples = static_cast<unsigned>(options.lightSamples);
    ctx.glossSamples = static_cast<unsigned>(options.glossSamples);
    ctx.pixelGrid = sampling::makeSampleGrid(ctx.samplesPerPixel);
    ctx.lightGrid = sampling::makeSampleGrid(static_cast<unsigned>(lightCount));
    ctx.glossGrid = sampling::makeSampleGrid(static_cast<unsigned>(glossCount));
    ctx.shutter = shutterOf(options);
    ctx.motion = !accel.bvh.motions.empty();
    return ctx;
}

}  // namespace vkrt::cpu
