#include "cpu_renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "camera.h"
#include "integrator.h"
#include "progress.h"
#include "render_context.h"
#include "sampling.h"

namespace vkrt {

namespace {

using cpu::Integrator;
using cpu::RenderContext;

// 16x16 pixels: small enough that two threads stay balanced on a 64x64 image, large enough that
// the tile counter is touched rarely.
constexpr int kTileSize = 16;

bool isFinite(const glm::vec3& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }

// One pixel: the mean of its rpp samples, summed in sample order in float (RENDERING.md §2).
// With `variance`, also the unbiased variance of the samples, from sums kept in double so that
// E[x^2] - E[x]^2 does not cancel away.
glm::vec3 renderPixel(const RenderContext& ctx, Integrator& integrator, int i, int j, std::uint64_t& nonFinite,
                      glm::vec3* variance = nullptr) {
    const auto pixel = static_cast<std::uint32_t>(j) * static_cast<std::uint32_t>(ctx.camera.nx) +
                       static_cast<std::uint32_t>(i);
    glm::vec3 sum(0.0f);
    glm::dvec3 sumD(0.0), sumSqD(0.0);
    for (std::uint32_t s = 0; s < ctx.samplesPerPixel; ++s) {
        const glm::vec2 offset = sampling::sample2D(ctx.sampler, ctx.pixelGrid, pixel, s, sampling::DIM_CAMERA, ctx.seed);
        // The lens sample is drawn only for a thin lens: a pinhole render is the same computation
        // as before depth of field existed.
        const glm::vec2 lens = ctx.camera.thinLens ? sampling::sample2D(ctx.sampler, ctx.pixelGrid, pixel, s, sampling::DIM_LENS, ctx.seed)
                                                   : glm::vec2(0.5f);
        // So is the time: a scene without motion is the same computation as before motion blur.
        float time = 0.0f;
        if (ctx.motion) {
            const float u = sampling::sample1D(ctx.sampler, ctx.pixelGrid, pixel, s, sampling::DIM_TIME, ctx.seed);
            time = ctx.shutter.x + (ctx.shutter.y - ctx.shutter.x) * u;
        }
        glm::vec3 c = integrator.cameraRadiance(cpu::cameraRay(ctx.camera, i, j, offset, lens), {pixel, s, time});
        if (!isFinite(c)) {
            ++nonFinite;
            c = glm::vec3(0.0f);
        }
        sum += c;
        if (variance) {
            sumD += glm::dvec3(c);
            sumSqD += glm::dvec3(c) * glm::dvec3(c);
        }
    }
    if (variance) {
        const double n = ctx.samplesPerPixel;
        *variance = n > 1.0 ? glm::vec3(glm::max((sumSqD - sumD * sumD / n) / (n - 1.0), glm::dvec3(0.0))) : glm::vec3(0.0f);
    }
    return sum / static_cast<float>(ctx.samplesPerPixel);
}

int threadCount(int requested, int tiles) {
    int n = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
    return std::clamp(n, 1, std::max(1, tiles));
}

}  // namespace

SceneAccel prepareCpuScene(const Scene& scene) { return buildSceneAccel(scene); }

Image renderCpu(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, RenderStats* stats,
                Image* sampleVariance) {
    const auto start = std::chrono::steady_clock::now();
    const RenderContext ctx = cpu::makeRenderContext(scene, accel, options);

    Image image(options.width, options.height);
    if (sampleVariance) *sampleVariance = Image(options.width, options.height);
    // Only the rows asked for (a --part); the others stay black.
    const glm::ivec2 rows = rowsOf(options);
    const int tilesX = (options.width + kTileSize - 1) / kTileSize;
    const int tilesY = (rows.y - rows.x + kTileSize - 1) / kTileSize;
    const int tileCount = tilesX * tilesY;
    const int threads = threadCount(options.threads, tileCount);

    std::atomic<int> nextTile{0};
    std::atomic<int> tilesDone{0};
    std::atomic<bool> stop{false};
    bool cancelled = false;
    std::exception_ptr failure;
    std::mutex mutex;  // guards cancelled, failure and the summed statistics
    cpu::RayCounts totalRays;
    std::uint64_t totalNonFinite = 0;
    Progress progress("cpu render", options.quiet);

    auto worker = [&] {
        Integrator integrator(ctx);
        std::uint64_t nonFinite = 0;
        try {
            for (;;) {
                if (stop.load()) break;
                if (options.cancel && options.cancel->load()) {
                    std::lock_guard lock(mutex);
                    cancelled = true;
                    stop = true;
                    break;
                }
                const int tile = nextTile.fetch_add(1);
                if (tile >= tileCount) break;
                const int x0 = (tile % tilesX) * kTileSize, y0 = rows.x + (tile / tilesX) * kTileSize;
                const int x1 = std::min(x0 + kTileSize, options.width), y1 = std::min(y0 + kTileSize, rows.y);
                for (int j = y0; j < y1; ++j)
                    for (int i = x0; i < x1; ++i)
                        image.at(i, j) = renderPixel(ctx, integrator, i, j, nonFinite,
                                                     sampleVariance ? &sampleVariance->at(i, j) : nullptr);
                progress.update(static_cast<double>(tilesDone.fetch_add(1) + 1) / tileCount);
            }
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!failure) failure = std::current_exception();
            stop = true;
        }
        std::lock_guard lock(mutex);
        totalRays += integrator.counts();
        totalNonFinite += nonFinite;
    };

    std::vector<std::jthread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    pool.clear();  // joins

    if (failure) std::rethrow_exception(failure);
    if (cancelled) throw RenderCancelled{};
    if (stats) {
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats->threads = threads;
        stats->cameraRays = totalRays.camera;
        stats->shadowRays = totalRays.shadow;
        stats->reflectionRays = totalRays.reflection;
        stats->refractionRays = totalRays.refraction;
        stats->nonFiniteSamples = totalNonFinite;
    }
    return image;
}

}  // namespace vkrt
