#include "frame_params.h"

#include <algorithm>

#include <cmath>
#include <stdexcept>
#include <string>

#include "environment_distribution.h"
#include "final_rays.h"
#include "sampling.h"
#include "used_shaders.h"

namespace vkrt {

namespace {

void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("GPU render: " + what);
}

}  // namespace

gpu::FrameParams makeFrameParams(const Scene& scene, const SceneAccel& accel, const RenderOptions& options) {
    require(options.width > 0 && options.height > 0,
            "image size " + std::to_string(options.width) + "x" + std::to_string(options.height) + " has no pixels");
    require(options.samplesPerPixel >= 1, "samples per pixel must be at least 1, not " + std::to_string(options.samplesPerPixel));
    require(options.lightSamples >= 1, "light samples must be at least 1, not " + std::to_string(options.lightSamples));
    require(options.glossSamples >= 1, "gloss samples must be at least 1, not " + std::to_string(options.glossSamples));
    require(options.maxDepth >= 0, "max depth must not be negative, not " + std::to_string(options.maxDepth));
    // Pixel indices and the light/gloss sample indices s*k + j are 32-bit on the device.
    const auto fits32 = [](long long a, long long b) { return a * b <= 0xffffffffLL; };
    require(fits32(options.width, options.height) && fits32(options.samplesPerPixel, options.lightSamples) &&
                fits32(options.samplesPerPixel, options.glossSamples),
            "image size or sample counts exceed 2^32");
    require(!scene.cameras.empty(), scene.path + " has no camera");
    require(options.camera >= 0 && options.camera < static_cast<int>(scene.cameras.size()),
            "camera " + std::to_string(options.camera) + " does not exist (the scene has " + std::to_string(scene.cameras.size()) +
                " camera(s))");

    const Camera& camera = scene.cameras[options.camera];
    const CameraBasis basis = cameraBasis(camera);
    const float planeWidth = camera.imagePlaneWidth;
    const float planeHeight = planeWidth * static_cast<float>(options.height) / static_cast<float>(options.width);
    const auto rpp = static_cast<std::uint32_t>(options.samplesPerPixel);
    const auto lightSamples = static_cast<std::uint32_t>(options.lightSamples);
    const auto glossSamples = static_cast<std::uint32_t>(options.glossSamples);

    gpu::FrameParams f{};
    // A pinhole keeps 0 and 0: the lanes are read only by a kernel built with HAS_THIN_LENS.
    f.cameraPosition = glm::vec4(camera.position, camera.thinLens() ? 0.5f * camera.aperture : 0.0f);
    f.cameraU = glm::vec4(basis.u, planeWidth);
    f.cameraV = glm::vec4(basis.v, planeHeight);
    f.cameraW = glm::vec4(basis.w, camera.focalLength);
    f.background = glm::vec4(options.background.value_or(scene.background), camera.thinLens() ? camera.focusDistance : 0.0f);
    f.image = glm::uvec4(static_cast<std::uint32_t>(options.width), static_cast<std::uint32_t>(options.height),
                         camera.type == CameraType::Orthographic ? gpu::CAMERA_ORTHOGRAPHIC : gpu::CAMERA_PERSPECTIVE, 0u);
    const FinalRays finals = finalRays(scene, options);
    f.image.w = (finals.bounceSeesLight ? 0u : gpu::FINAL_BOUNCE_DARK) | (finals.reflectionSeesLight ? 0u : gpu::FINAL_REFLECTION_DARK) |
                (pathTraced(scene) ? gpu::PATH_DIELECTRIC_ONE_BRANCH : 0u);
    f.sampling = glm::uvec4(static_cast<std::uint32_t>(options.sampler), rpp, lightSamples, glossSamples);
    f.scene = glm::uvec4(options.seed, static_cast<std::uint32_t>(options.maxDepth), static_cast<std::uint32_t>(scene.lights.size()),
                         accel.bvh.topRoot);
    f.pixelGrid = sampling::makeSampleGrid(rpp);
    f.lightGrid = sampling::makeSampleGrid(rpp * lightSamples);
    f.glossGrid = sampling::makeSampleGrid(rpp * glossSamples);
    const glm::vec2 shutter = shutterOf(options);  // read only by a kernel built with HAS_MOTION
    f.shutter = glm::vec4(shutter.x, shutter.y, 0.0f, 0.0f);
    // The environment's face size and its distribution's cells (environment_distribution.h: C = min(N, 64)).
    const auto faceSize = options.environment ? static_cast<std::uint32_t>(scene.environment.faceSize) : 0u;
    f.lighting = glm::uvec4(static_cast<std::uint32_t>(scene.emitters.size()), static_cast<std::uint32_t>(options.estimator),
                            faceSize, std::min(faceSize, kMaxEnvironmentCells));
    return f;
}

}  // namespace vkrt
