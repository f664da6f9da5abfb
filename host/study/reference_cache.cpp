#include "reference_cache.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

#include <xxhash.h>

namespace vkrt::study {

namespace {

// Bump when the meaning of the cached reference or noise changes (the image definition, the noise
// estimate), so that old cache entries are not reused. The masks have their own version in their
// file name: they are cheap to recompute and change independently.
// 2: Diffuse surfaces are path traced and shape emitters are geometry (docs/RENDERING.md §4-§5);
//    format 1 references of such scenes show the Lambertian and point-light stand-ins.
constexpr int kCacheFormat = 2;
// 4: the indirect and emitter regions; shape emitters count in the penumbra.
constexpr int kMasksFormat = 4;

std::string hexFloat(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%a", static_cast<double>(v));
    return buf;
}

// Every option that changes the reference's expectation, and so its key. Not the estimator: all
// have the same expectation, and the reference is always rendered with kReferenceEstimator, so a
// sweep of other estimators (--estimators) reuses it.
std::string describe(const ReferenceSpec& spec) {
    const RenderOptions& o = spec.options;
    std::ostringstream s;
    s << "vkrt reference format " << kCacheFormat << "\n"
      << "size " << o.width << "x" << o.height << "\n"
      << "camera " << o.camera << "\n"
      << "max-depth " << o.maxDepth << "\n"
      << "light-samples " << o.lightSamples << "\n"
      << "gloss-samples " << o.glossSamples << "\n"
      << "lens " << hexFloat(spec.lens.x) << "," << hexFloat(spec.lens.y) << "\n"
      << "shutter " << hexFloat(shutterOf(o).x) << "," << hexFloat(shutterOf(o).y) << "\n"
      << "background " << (o.background ? hexFloat(o.background->r) + "," + hexFloat(o.background->g) + "," + hexFloat(o.background->b) : "scene") << "\n"
      << "environment " << (o.environment ? "scene" : "off") << "\n"
      << "rpp " << spec.rpp << " as two halves with seeds " << kReferenceSeedA << ", " << kReferenceSeedB << "\n"
      << "sampler " << samplerName(spec.sampler) << "\n"
      << "device " << deviceName(spec.device) << "\n";
    return s.str();
}

// Writes through a temporary name and renames, so a concurrent reader never sees half a file.
void writeAtomically(const Image& image, const std::filesystem::path& path) {
    std::filesystem::path tmp = path;
    tmp.replace_filename(path.stem().string() + ".tmp" + std::to_string(::getpid()) + path.extension().string());
    writeImage(image, tmp.string());
    std::filesystem::rename(tmp, path);
}

}  // namespace

std::filesystem::path defaultCacheDir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "vkrt";
    if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / ".cache" / "vkrt";
    return std::filesystem::current_path() / ".vkrt-cache";
}

std::string referenceKey(const std::string& sceneText, const ReferenceSpec& spec) {
    const std::string text = describe(spec) + "scene\n" + sceneText;
    char buf[24];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(XXH64(text.data(), text.size(), 0)));
    return buf;
}

Reference loadOrRenderReference(StudyRenderer& renderer, const PreparedScene& scene,
                                const std::string& sceneText, const ReferenceSpec& spec,
                                const std::filesystem::path& cacheDir, std::ostream& log, const HalfRenderer& renderHalf) {
    if (spec.rpp < 2) throw std::invalid_argument("reference rpp must be at least 2 (two halves), not " + std::to_string(spec.rpp));
    Reference ref;
    ref.key = referenceKey(sceneText, spec);
    const std::filesystem::path dir = cacheDir / "references";
    ref.imagePath = dir / (ref.key + ".exr");
    const std::filesystem::path noisePath = dir / (ref.key + "_noise.exr");
    const std::filesystem::path masksPath = dir / (ref.key + "_masks_v" + std::to_string(kMasksFormat) + ".png");
    const std::filesystem::path infoPath = dir / (ref.key + ".txt");

    ProbeOptions probe;
    probe.threads = spec.options.threads;
    auto loadOrFindMasks = [&] {
        if (std::filesystem::exists(masksPath)) {
            ref.masks = masksFromImage(readImage(masksPath.string()));
            return;
        }
        const auto start = std::chrono::steady_clock::now();
        ref.masks = findRegions(*scene.scene, scene.cpu, spec.options, probe);
        writeAtomically(masksToImage(ref.masks), masksPath);
        log << "reference: region masks in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
    };

    if (std::filesystem::exists(ref.imagePath) && std::filesystem::exists(noisePath)) {
        ref.image = readImage(ref.imagePath.string());
        ref.noise = readImage(noisePath.string());
        loadOrFindMasks();
        const bool sized = [&] {
            for (const Image* i : {&ref.image, &ref.noise})
                if (i->width != spec.options.width || i->height != spec.options.height) return false;
            return ref.masks.width == spec.options.width && ref.masks.height == spec.options.height;
        }();
        if (!sized) throw std::runtime_error(ref.imagePath.string() + ": cached reference has the wrong size; delete it");
        ref.fromCache = true;
        log << "reference: cached " << ref.imagePath.string() << "\n";
        return ref;
    }

    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error(dir.string() + ": cannot create the reference cache: " + ec.message());
    log << "reference: rendering " << spec.rpp << " rpp (" << samplerName(spec.sampler) << ") on the "
        << deviceName(spec.device) << " into " << ref.imagePath.string() << "\n"
        << std::flush;

    RenderOptions half = spec.options;
    half.sampler = spec.sampler;
    half.estimator = kReferenceEstimator;
    half.samplesPerPixel = spec.rpp / 2;
    const HalfRenderer render = renderHalf ? renderHalf : [&](const RenderOptions& o) { return renderer.render(spec.device, scene, o); };
    half.seed = kReferenceSeedA;
    const TimedRender a = render(half);
    half.seed = kReferenceSeedB;
    const TimedRender b = render(half);
    ref.seconds = a.seconds + b.seconds;

    ref.image = Image(a.image.width, a.image.height);
    ref.noise = Image(a.image.width, a.image.height);
    for (std::size_t k = 0; k < ref.image.pixels.size(); ++k) {
        const glm::vec3 d = a.image.pixels[k] - b.image.pixels[k];
        ref.image.pixels[k] = 0.5f * (a.image.pixels[k] + b.image.pixels[k]);
        // Var(A - B) = 2 v_half and the mean has v_half / 2, so (A - B)^2 / 4 estimates it.
        ref.noise.pixels[k] = 0.25f * d * d;
    }
    log << "reference: " << ref.seconds << " s\n";
    writeAtomically(ref.image, ref.imagePath);
    writeAtomically(ref.noise, noisePath);
    loadOrFindMasks();
    std::ofstream info(infoPath);
    info << describe(spec) << "estimator " << estimatorName(kReferenceEstimator) << " (not in the key: every estimator has the same expectation)\n"
         << "render seconds " << ref.seconds << "\n";
    return ref;
}

}  // namespace vkrt::study
