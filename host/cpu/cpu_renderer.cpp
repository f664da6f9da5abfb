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
#include "float_range.h"
#include "integrator.h"
#include "progress.h"
#include "render_context.h"
#include "sampling.h"

namespace vkrt {

namespace {

using cpu::Integrator;
using cpu::RenderContext;

// 8x8 pixels: small enough that two threads stay balanced on a 96x96 image, large enough that
// the tile counter is touched rarely.
constexpr int kTileSize = 8;

bool isFinite(const glm::vec3& c) { return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z); }

// Adds samples [first, last) of pixel (i, j) to `sum`, in sample order in float (RENDERING.md §2):
// a pixel rendered in several passes sums exactly as one rendered in one. With `variance` (one pass
// over all the samples), also the unbiased variance of the samples, from sums kept in double so that
// E[x^2] - E[x]^2 does not cancel away.
// With `oddSum`, the odd-numbered samples are also summed there (the second half of adaptive
// sampling's pair, error_estimate.h).
void addPixelSamples(const RenderContext& ctx, Integrator& integrator, int i, int j, std::uint32_t first,
                     std::uint32_t last, glm::vec3& sum, std::uint64_t& nonFinite, glm::vec3* variance = nullptr,
                     glm::vec3* oddSum = nullptr) {
    const auto pixel = static_cast<std::uint32_t>(j) * static_cast<std::uint32_t>(ctx.camera.nx) +
                       static_cast<std::uint32_t>(i);
    glm::dvec3 sumD(0.0), sumSqD(0.0);
    for (std::uint32_t s = first; s < last; ++s) {
        const std::uint32_t index = sampling::sampleIndex(ctx.sampler, s), seed = sampling::sampleSeed(ctx.sampler, ctx.seed, s);
        const glm::vec2 offset = sampling::sample2D(ctx.sampler, ctx.pixelGrid, pixel, index, sampling::DIM_CAMERA, seed);
        // The lens sample is drawn only for a thin lens: a pinhole render is the same computation
        // as before depth of field existed.
        const glm::vec2 lens = ctx.camera.thinLens ? sampling::sample2D(ctx.sampler, ctx.pixelGrid, pixel, index, sampling::DIM_LENS, seed)
                                                   : glm::vec2(0.5f);
        // So is the time: a scene without motion is the same computation as before motion blur.
        float time = 0.0f;
        if (ctx.motion) {
            const float u = sampling::sample1D(ctx.sampler, ctx.pixelGrid, pixel, index, sampling::DIM_TIME, seed);
            time = ctx.shutter.x + (ctx.shutter.y - ctx.shutter.x) * u;
        }
        glm::vec3 c = integrator.cameraRadiance(cpu::cameraRay(ctx.camera, i, j, offset, lens), {pixel, index, seed, time});
        if (!isFinite(c)) {
            ++nonFinite;
            c = glm::vec3(0.0f);
        }
        sum += c;
        if (oddSum && (s & 1u) != 0u) *oddSum += c;
        if (variance) {
            sumD += glm::dvec3(c);
            sumSqD += glm::dvec3(c) * glm::dvec3(c);
        }
    }
    if (variance) {
        const double n = last - first;
        *variance = n > 1.0 ? glm::vec3(glm::max((sumSqD - sumD * sumD / n) / (n - 1.0), glm::dvec3(0.0))) : glm::vec3(0.0f);
    }
}

// The rows' pixels: sums / samples (the other rows stay black).
Image meanOf(const Image& sums, glm::ivec2 rows, int samples) {
    Image image(sums.width, sums.height);
    const auto n = static_cast<float>(samples);
    for (int j = rows.x; j < rows.y; ++j)
        for (int i = 0; i < sums.width; ++i) image.at(i, j) = sums.at(i, j) / n;
    return image;
}

int threadCount(int requested, int tiles) {
    int n = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
    return std::clamp(n, 1, std::max(1, tiles));
}

// What the threads of one pass share: the tile counter, the first failure, the rays they traced.
struct PassTotals {
    cpu::RayCounts rays;
    std::uint64_t nonFinite = 0;
};

// Calls work(integrator, i, j, nonFinite) for every pixel of `rows`, 16x16 tiles handed to
// `threads` threads; each pixel's work is its own, so the result does not depend on the threads.
// progress(tilesDone / tileCount) after each tile. Throws RenderCancelled when *options.cancel
// becomes true, or the first worker's exception. `order` (optional): the tiles in the order the
// threads take them.
template <class Work, class OnTile>
void runTiles(const RenderContext& ctx, const RenderOptions& options, glm::ivec2 rows, int threads, PassTotals& totals,
              const Work& work, const OnTile& onTile, const std::vector<int>* order = nullptr) {
    const int tilesX = (options.width + kTileSize - 1) / kTileSize;
    const int tilesY = (rows.y - rows.x + kTileSize - 1) / kTileSize;
    const int tileCount = tilesX * tilesY;
    std::atomic<int> nextTile{0};
    std::atomic<int> tilesDone{0};
    std::atomic<bool> stop{false};
    bool cancelled = false;
    std::exception_ptr failure;
    std::mutex mutex;  // guards cancelled, failure and the totals

    auto worker = [&] {
        Integrator integrator(ctx);
        std::uint64_t nonFinite = 0;
        try {
            for (;;) {
                // The cancel flag first: a worker that stopped mid-tile for it comes back here.
                if (options.cancel && options.cancel->load()) {
                    std::lock_guard lock(mutex);
                    cancelled = true;
                    stop = true;
                    break;
                }
                if (stop.load()) break;
                const int taken = nextTile.fetch_add(1);
                if (taken >= tileCount) break;
                const int tile = order ? (*order)[static_cast<std::size_t>(taken)] : taken;
                const int x0 = (tile % tilesX) * kTileSize, y0 = rows.x + (tile / tilesX) * kTileSize;
                const int x1 = std::min(x0 + kTileSize, options.width), y1 = std::min(y0 + kTileSize, rows.y);
                // Cancelling is also asked per pixel: a tile of a high-rpp render takes seconds.
                for (int j = y0; j < y1 && !stop.load(std::memory_order_relaxed); ++j)
                    for (int i = x0; i < x1; ++i) {
                        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
                            stop = true;
                            break;
                        }
                        work(integrator, i, j, nonFinite);
                    }
                onTile(static_cast<double>(tilesDone.fetch_add(1) + 1) / tileCount);
            }
        } catch (...) {
            std::lock_guard lock(mutex);
            if (!failure) failure = std::current_exception();
            stop = true;
        }
        std::lock_guard lock(mutex);
        totals.rays += integrator.counts();
        totals.nonFinite += nonFinite;
    };
    {
        std::vector<std::jthread> pool;
        for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
        worker();
    }  // joins
    if (failure) std::rethrow_exception(failure);
    if (cancelled) throw RenderCancelled{};
}

int tilesOf(const RenderOptions& options, glm::ivec2 rows) {
    return ((options.width + kTileSize - 1) / kTileSize) * ((rows.y - rows.x + kTileSize - 1) / kTileSize);
}

void copyTotals(const PassTotals& totals, int threads, RenderStats& stats) {
    stats.threads = threads;
    stats.cameraRays = totals.rays.camera;
    stats.shadowRays = totals.rays.shadow;
    stats.reflectionRays = totals.rays.reflection;
    stats.refractionRays = totals.rays.refraction;
    stats.bounceRays = totals.rays.bounce;
    stats.nonFiniteSamples = totals.nonFinite;
}

}  // namespace

SceneAccel prepareCpuScene(const Scene& scene) { return buildSceneAccel(scene); }

Image renderCpu(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, RenderStats* stats,
                Image* sampleVariance) {
    const auto start = std::chrono::steady_clock::now();
    const RenderContext ctx = cpu::makeRenderContext(scene, accel, options);

    Image sums(options.width, options.height);  // zero
    if (sampleVariance) *sampleVariance = Image(options.width, options.height);
    // Only the rows asked for (a --part); the others stay black.
    const glm::ivec2 rows = rowsOf(options);
    const int threads = threadCount(options.threads, tilesOf(options, rows));

    // The passes' sample ranges: one pass unless the render is progressive (the variance needs all
    // of a pixel's samples in one pass).
    const std::vector<int> ends = checkpointEnds(static_cast<int>(ctx.samplesPerPixel), sampleVariance ? 1 : options.checkpoints);
    std::uint32_t first = 0, last = 0;
    PassTotals totals;
    Progress progress("cpu render", options.quiet);

    for (const int end : ends) {
        first = last;
        last = static_cast<std::uint32_t>(end);
        runTiles(ctx, options, rows, threads, totals,
                 [&](Integrator& integrator, int i, int j, std::uint64_t& nonFinite) {
                     addPixelSamples(ctx, integrator, i, j, first, last, sums.at(i, j), nonFinite,
                                     sampleVariance ? &sampleVariance->at(i, j) : nullptr);
                 },
                 [&](double done) { progress.update((done * (last - first) + first) / ctx.samplesPerPixel); });
        if (last < ctx.samplesPerPixel && options.onCheckpoint)
            options.onCheckpoint->checkpoint([&] {
                Image soFar = meanOf(sums, rows, static_cast<int>(last));
                clampOverflowedPixels(soFar);
                return soFar;
            }(), static_cast<int>(last));
    }
    if (stats) {
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        copyTotals(totals, threads, *stats);
    }
    Image image = meanOf(sums, rows, ctx.samplesPerPixel);
    const std::size_t overflowed = clampOverflowedPixels(image);
    if (stats) stats->overflowedPixels = overflowed;
    return image;
}

CpuSampleRanges::CpuSampleRanges(const Scene& scene, const SceneAccel& accel, const RenderOptions& options)
    : options_(options), ctx_(std::make_unique<RenderContext>(cpu::makeRenderContext(scene, accel, options))),
      rows_(rowsOf(options)), threads_(threadCount(options.threads, tilesOf(options, rows_))) {}

CpuSampleRanges::~CpuSampleRanges() = default;

void CpuSampleRanges::add(const std::vector<std::uint32_t>& next, adaptive::PixelAccumulation& acc) {
    const auto start = std::chrono::steady_clock::now();
    PassTotals totals;
    Progress progress("cpu round", options_.quiet);
    // The tiles with the most samples to add first: a round's tiles differ in cost by up to the
    // ratio of their counts, and a costly tile taken last would leave the other threads idle.
    const int tilesX = (options_.width + kTileSize - 1) / kTileSize;
    const int tileCount = tilesOf(options_, rows_);
    std::vector<std::uint64_t> cost(static_cast<std::size_t>(tileCount), 0);
    for (int j = rows_.x; j < rows_.y; ++j)
        for (int i = 0; i < options_.width; ++i) {
            const std::size_t p = acc.index(i, j);
            cost[static_cast<std::size_t>((j - rows_.x) / kTileSize * tilesX + i / kTileSize)] += next[p] - acc.count[p];
        }
    std::vector<int> order(static_cast<std::size_t>(tileCount));
    for (int t = 0; t < tileCount; ++t) order[static_cast<std::size_t>(t)] = t;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[static_cast<std::size_t>(a)] > cost[static_cast<std::size_t>(b)]; });
    runTiles(*ctx_, options_, rows_, threads_, totals,
             [&](Integrator& integrator, int i, int j, std::uint64_t& nonFinite) {
                 const std::size_t p = acc.index(i, j);
                 if (next[p] > acc.count[p])
                     addPixelSamples(*ctx_, integrator, i, j, acc.count[p], next[p], acc.sum[p], nonFinite, nullptr, &acc.oddSum[p]);
             },
             [&](double done) { progress.update(done); }, &order);
    acc.count = next;
    RenderStats round;
    copyTotals(totals, threads_, round);
    stats_.threads = threads_;
    stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats_.cameraRays += round.cameraRays;
    stats_.shadowRays += round.shadowRays;
    stats_.reflectionRays += round.reflectionRays;
    stats_.refractionRays += round.refractionRays;
    stats_.bounceRays += round.bounceRays;
    stats_.nonFiniteSamples += round.nonFiniteSamples;
}

}  // namespace vkrt
