#include "check_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "cpu_renderer.h"
#include "exposure.h"
#include "heat_map.h"
#include "image.h"
#include "image_check.h"
#include "output_file.h"
#include "render_steps.h"
#include "scene_accel.h"

namespace vkrt {

namespace {

// The renders a mistake needs use at most this many rpp: the test accounts for their noise, and
// a scene with several lights needs one render per light.
constexpr int kMistakeRenderRpp = 16;
// Lights tried one by one for "a light is missing"; a scene with more gets no such diagnosis.
constexpr std::size_t kMaxLightsTried = 8;

std::string besideImage(const std::string& image, const char* suffix) {
    const std::filesystem::path path(image);
    return (path.parent_path() / (path.stem().string() + suffix)).string();
}

std::string colour255(const glm::vec3& c) {
    char text[64];
    std::snprintf(text, sizeof text, "(%d, %d, %d)/255", static_cast<int>(std::lround(c.x * 255.0f)),
                  static_cast<int>(std::lround(c.y * 255.0f)), static_cast<int>(std::lround(c.z * 255.0f)));
    return text;
}

// "x,y,z" with %g (the form --bg and --up take), or "(x, y, z)" for a position.
std::string numbers(const glm::vec3& v, const char* separator) {
    char text[96];
    std::snprintf(text, sizeof text, "%g%s%g%s%g", v.x, separator, v.y, separator, v.z);
    return text;
}

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f%%", 100.0 * fraction);
    return text;
}

CheckReference renderReference(const Scene& scene, const SceneAccel& accel, const RenderOptions& options) {
    CheckReference reference;
    reference.rpp = options.samplesPerPixel;
    RenderStats stats;
    reference.mean = renderCpu(scene, accel, options, &stats, &reference.sampleVariance);
    return reference;
}

// The outcome of trying one mistake.
struct Trial {
    std::string name, explanation;
    double passedFraction = 0.0;
    bool explains = false;
};

// The mistakes that need a render of their own: a background colour other than the scene's (or
// no environment map), and each light left out in turn. They all render with the scene's tree:
// it holds the geometry, the shape emitters and the environment map, never the point and area
// lights, so a scene that differs only in its lights is drawn by it as it is.
std::vector<Trial> tryRenderedMistakes(const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                                       const Image& yours, const CheckReference& reference, const PixelTestOptions& test) {
    std::vector<Trial> trials;
    RenderOptions cheap = options;
    cheap.samplesPerPixel = std::min(options.samplesPerPixel, kMistakeRenderRpp);
    cheap.quiet = true;
    auto attempt = [&](const std::string& name, const std::string& explanation, const Scene& variant, const RenderOptions& o) {
        const PixelTestResult r = testPixels(yours, renderReference(variant, accel, o), test);
        trials.push_back({name, explanation, r.passedFraction(), r.same});
        return r.same;
    };

    const bool environmentShows = options.environment && scene.environment.faceSize > 0;
    const glm::vec3 sceneBackground = options.background.value_or(scene.background);
    const ColourCount common = commonFailingColour(yours, reference, test);
    if (common.count > 0) {
        RenderOptions other = cheap;
        other.background = common.colour;
        other.environment = false;
        std::string explanation = "your background is " + colour255(common.colour);
        if (environmentShows) explanation += " where vkrt shows the scene's environment map (--no-environment renders without it)";
        else explanation += " where the scene's is " + colour255(sceneBackground);
        explanation += "; vkrt renders yours with --bg " + numbers(common.colour, ",");
        if (colour255(common.colour) == colour255(glm::vec3(kReferenceLookBackground)))
            explanation += " (the instructor's reference look: --look reference)";
        if (attempt(environmentShows ? "no environment map" : "background colour", explanation, scene, other)) return trials;
    }
    if (scene.lights.size() > 1 && scene.lights.size() <= kMaxLightsTried) {
        Scene without = scene;  // one copy, its lights set for each try
        for (std::size_t k = 0; k < scene.lights.size(); ++k) {
            without.lights = scene.lights;
            without.lights.erase(without.lights.begin() + static_cast<std::ptrdiff_t>(k));
            const Light& light = scene.lights[k];
            const std::string name = "light " + std::to_string(k + 1) + " of " + std::to_string(scene.lights.size()) + " missing";
            const std::string explanation =
                "your image has none of the light of the scene's " + std::string(light.type == LightType::Point ? "point" : "area") +
                " light at (" + numbers(light.position, ", ") + "), " + light.where.file + " line " +
                std::to_string(light.where.line) + ": is every light read and its light summed?";
            if (attempt(name, explanation, without, cheap)) return trials;
        }
    }
    return trials;
}

}  // namespace

int runCheck(CommandLine& cl) {
    const Image yours = readImage(cl.imagePath);
    const std::string referencePath = besideImage(cl.imagePath, "_vkrt_reference.png");
    const std::string diffPath = besideImage(cl.imagePath, "_vkrt_diff.png");
    for (const std::string& output : {referencePath, diffPath}) {
        checkOutputBeforeRendering(output, cl.scenePath);
        checkNotTheInput(output, cl.imagePath);
    }
    cl.outputPath = referencePath;  // loadWithWarnings refuses outputs that are the scene's inputs
    cl.heatMapPath = diffPath;
    cl.render.width = yours.width;
    cl.render.height = yours.height;
    checkImageFitsInMemory(yours.width, yours.height);
    const Scene scene = loadWithWarnings(cl);

    const auto start = std::chrono::steady_clock::now();
    const SceneAccel accel = prepareCpuScene(scene);
    CheckReference reference = renderReference(scene, accel, cl.render);
    const double seconds = secondsSince(start);
    // --exposure: your image was made at this exposure; a sample scaled by k has k^2 the variance.
    reference.mean = withExposure(std::move(reference.mean), cl.exposure);
    reference.sampleVariance = withExposure(withExposure(std::move(reference.sampleVariance), cl.exposure), cl.exposure);
    PixelTestOptions test;
    // 8-bit files hold display values, clamped to [0,1]; an EXR holds linear radiance as is.
    test.clampReference = lowerExtension(cl.imagePath) != ".exr";
    const PixelTestResult result = testPixels(yours, reference, test);
    writeImage(reference.mean, referencePath);
    writeImage(withDifferenceLegend(checkMap(yours, reference, test), {{glm::vec3(kWithinNoiseGrey), "within noise"}}), diffPath);

    std::printf("scene            %s (camera %d)\n", cl.scenePath.c_str(), cl.render.camera);
    std::printf("your image       %s (%dx%d)\n", cl.imagePath.c_str(), yours.width, yours.height);
    std::printf("vkrt reference   cpu, %d %s rpp, seed %u, %.2f s -> %s\n", reference.rpp,
                samplerName(cl.render.sampler).c_str(), cl.render.seed, seconds, referencePath.c_str());
    std::printf("pixel test       |yours - vkrt| within %.0f/255 + %.2f standard errors of vkrt's noise (yours counted "
                "as >= 1 sample per pixel; alpha %.2f over all values)\n",
                test.slack * 255.0, result.zLimit, test.alpha);
    std::printf("pixels passing   %s (needs >= %s)\n", percent(result.passedFraction()).c_str(),
                percent(test.requiredFraction).c_str());
    std::printf("mean difference  %+.2f/255 (%s)\n", result.meanSignedDifference * 255.0,
                result.meanSignedDifference >= 0.0 ? "yours brighter" : "yours darker");
    std::printf("difference map   %s (black: equal, grey: within noise, red to yellow: differs, scale in /255)\n",
                diffPath.c_str());
    if (result.same) {
        std::printf("verdict          SAME: your image is vkrt's picture of this scene, within its noise\n");
        return kExitSamePicture;
    }

    // Which common mistake explains the difference: the image-only ones first (no render), then
    // those that need one. The first that passes the test is the diagnosis.
    std::vector<Trial> trials;
    const bool square = yours.width == yours.height;
    for (const Mistake& mistake : imageMistakes()) {
        if (mistake.swapsAxes && !square) continue;
        const PixelTestResult r = testPixels(yours, mistake.apply(reference), test);
        trials.push_back({mistake.name, mistake.explanation, r.passedFraction(), r.same});
    }
    auto best = [&] {
        return std::max_element(trials.begin(), trials.end(),
                                [](const Trial& a, const Trial& b) { return a.passedFraction < b.passedFraction; });
    };
    if (!best()->explains) {
        const std::vector<Trial> rendered = tryRenderedMistakes(scene, accel, cl.render, yours, reference, test);
        trials.insert(trials.end(), rendered.begin(), rendered.end());
    }
    const Trial& closest = *best();
    if (closest.explains) {
        std::printf("likely mistake   %s: with it, %s of pixels pass\n", closest.name.c_str(), percent(closest.passedFraction).c_str());
        std::printf("                 %s\n", closest.explanation.c_str());
    } else {
        std::printf("likely mistake   none of the %zu common ones tried explains it (the closest, %s, passes %s)\n",
                    trials.size(), closest.name.c_str(), percent(closest.passedFraction).c_str());
        if (fractionFailingWhereReferenceBlack(yours, reference, test) >= 0.5)
            std::printf("                 most differing pixels are black in vkrt's image but lit in yours: an ambient "
                        "term? The course's shaders have none (unlit is black)\n");
    }
    std::printf("verdict          DIFFERENT: your image is not vkrt's picture of this scene\n");
    return kExitDifferentPicture;
}

}  // namespace vkrt
