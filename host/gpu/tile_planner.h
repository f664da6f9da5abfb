// Splits a render into submissions sized from measured times so that no submission runs much
// longer than a target (~0.3 s): the progress bar moves, Ctrl-C is answered quickly, and a real
// GPU's watchdog never sees a long dispatch.
//
// The image is one tile (or a few full-width bands when it has more 8x8 blocks than one dispatch
// may have workgroups). render.comp maps workgroup g of a tile to block (g * stride) % workgroups
// with a stride near workgroups / golden ratio, so any run of consecutive workgroups covers the
// whole tile evenly. A submission is such a run of workgroups (dispatched with vkCmdDispatchBase)
// for one sample pass, or, when the budget allows, every workgroup for several passes. Every
// submission therefore samples the image's cost evenly: its time predicts the next one's even
// when the scene's expensive objects sit in one corner (spatial tiles would meet them suddenly).
//
// Order: sample pass by sample pass over a tile (pass s reaches every pixel before pass s + 1
// starts), so every pixel sums its samples in sample order whatever the submission sizes: the
// image never depends on them.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "device_host.h"

namespace vkrt {

struct TileRect {
    std::uint32_t x = 0, y = 0, width = 0, height = 0;
    std::uint64_t pixels() const { return static_cast<std::uint64_t>(width) * height; }
    // 8x8 blocks = workgroups of render.comp.
    std::uint32_t workgroups() const { return ((width + 7) / 8) * ((height + 7) / 8); }
};

struct Submission {
    TileRect tile;
    std::uint32_t firstWorkgroup = 0;  // workgroups [first, first + count) of the tile's interleaved order
    std::uint32_t workgroupCount = 0;
    std::uint32_t firstSample = 0;     // sample passes [first, first + count), one dispatch each (a pass
                                       // computes k samples per pixel: sample_batching.h)
    std::uint32_t sampleCount = 0;
    std::size_t tileIndex = 0;         // into TilePlanner::tiles()
    bool endsPasses = false;           // the run reaches the tile's last workgroup: passes
                                       // [0, firstSample + sampleCount) of the tile are complete
};

struct TilingPolicy {
    double targetSeconds = 0.3;              // aim per submission (0.25 - 0.5 s asked)
    std::uint64_t firstPixelSamples = 4096;  // the probe before anything was measured (64 workgroups)
    double maxGrowth = 4.0;                  // a submission is at most this many times the previous one's work
    // Workgroups of one dispatch: maxComputeWorkGroupCount.x, and render.comp's
    // g * stride % workgroups must not overflow 32 bits, so at most 65535.
    std::uint32_t maxWorkgroups = 65535;
    // Tests: fixed sizes instead of measured ones (0 = adaptive / automatic).
    std::uint32_t fixedTileWidth = 0, fixedTileHeight = 0;  // tiles in raster order
    std::uint32_t fixedWorkgroups = 0;                      // workgroups per submission
    std::uint32_t fixedSamples = 0;                         // passes per submission (whole tile only)
};

class TilePlanner {
public:
    TilePlanner(std::uint32_t width, std::uint32_t height, std::uint32_t samples, const TilingPolicy& policy);

    bool done() const { return tile_ >= tiles_.size(); }
    // The next piece of work; only valid when !done().
    Submission next();
    // Progressive renders: no submission runs past one of these pass counts (increasing), so that
    // every tile's passes end exactly on each of them (RenderOptions::checkpoints).
    void stopAtPasses(std::vector<int> ends) { stops_ = std::move(ends); }
    // How long the submission returned by the last next() took; adapts the following sizes.
    void reportSeconds(double seconds);
    double fractionDone() const { return static_cast<double>(doneUnits_) / static_cast<double>(totalUnits_); }
    const std::vector<TileRect>& tiles() const { return tiles_; }

private:
    std::uint64_t budgetPixelSamples() const;

    std::uint32_t samples_;
    TilingPolicy policy_;
    std::vector<int> stops_;
    std::vector<TileRect> tiles_;
    // Position: tile, sample pass, first workgroup of the pass not yet submitted.
    std::size_t tile_ = 0;
    std::uint32_t sample_ = 0;
    std::uint32_t workgroup_ = 0;
    // Measurements, in workgroup-samples (one 8x8 block for one sample).
    double secondsPerUnit_ = 0.0;  // 0 until the first report
    std::uint64_t lastUnits_ = 0;
    std::uint64_t doneUnits_ = 0;
    std::uint64_t totalUnits_ = 0;
};

// The tiles of an image: one, or full-width bands of at most maxWorkgroups blocks, or the fixed
// tile size in raster order.
std::vector<TileRect> planTiles(std::uint32_t width, std::uint32_t height, const TilingPolicy& policy);

// A workgroup stride for `workgroups` blocks: coprime to it (so block = g * stride % workgroups,
// render.comp's mapping, is a permutation) and near workgroups / golden ratio, so that any run of
// consecutive workgroups - a submission, or what lavapipe hands one thread - is spread evenly
// over the tile.
std::uint32_t interleaveStride(std::uint32_t workgroups);

// PassParams for `count` samples from `firstSample` over `tile` (device_host.h; render.comp's
// block mapping).
gpu::PassParams passParams(const TileRect& tile, std::uint32_t firstSample, std::uint32_t count = 1);

}  // namespace vkrt
