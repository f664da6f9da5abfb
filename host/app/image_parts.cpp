#include "image_parts.h"

#include <filesystem>
#include <sstream>

namespace vkrt {

ImageAttributes partAttributes(const CommandLine& cl, const std::string& device) {
    const RenderOptions& r = cl.render;
    std::error_code ec;
    const std::filesystem::path scene = std::filesystem::weakly_canonical(cl.scenePath, ec);
    std::ostringstream render;
    render << "scene " << (ec ? cl.scenePath : scene.string()) << "; " << r.width << "x" << r.height << "; rpp "
           << r.samplesPerPixel << "; sampler " << samplerName(r.sampler) << "; seed " << r.seed << "; light-samples "
           << r.lightSamples << "; gloss-samples " << r.glossSamples << "; max-depth " << r.maxDepth << "; camera "
           << (cl.camera ? std::to_string(*cl.camera) : std::string("default"));
    if (r.background) render << "; bg " << r.background->r << "," << r.background->g << "," << r.background->b;
    if (cl.focusDistance) render << "; focus " << *cl.focusDistance;
    if (cl.aperture) render << "; aperture " << *cl.aperture;
    if (cl.up) render << "; up " << cl.up->x << "," << cl.up->y << "," << cl.up->z;
    if (r.shutter) render << "; shutter " << r.shutter->x << "," << r.shutter->y;
    // A part's pixels carry its --exposure: parts of one image must share it.
    render << "; exposure " << cl.exposure;
    if (cl.general) render << "; general kernel";
    // Every estimator has the same expectation, but not the same samples: parts must share one.
    render << "; estimator " << estimatorName(r.estimator);
    if (!r.environment) render << "; no environment";
    // The CPU reference and a GPU agree to rounding, not bit for bit: parts must share a device kind.
    render << "; device " << (device.rfind("cpu", 0) == 0 ? std::string("cpu") : "gpu " + device.substr(0, device.find(" [")));
    const glm::ivec2 rows = rowsOf(r);
    return {{"vkrt:part", std::to_string(cl.part) + "/" + std::to_string(cl.parts)},
            {"vkrt:rows", std::to_string(rows.x) + " " + std::to_string(rows.y)},
            {"vkrt:render", render.str()}};
}

}  // namespace vkrt
