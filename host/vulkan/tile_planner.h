// Splits a render into submissions of (tile, run of sample passes), sized from measured times so
// that no submission runs much longer than a target (~0.3 s): the progress bar moves, Ctrl-C is
// answered quickly, and a real GPU's watchdog never sees a long dispatch.
//
// Order: tiles in raster order (bands of rows, left to right within a band); each tile runs all
// its samples in order 0..rpp-1 before the next tile starts, so every pixel's sum is accumulated
// in sample order whatever the tiling. A pixel's value therefore never depends on the tiling.
// When a tile turns out too expensive for one sample pass per submission (it was sized from a
// cheaper region), its remaining work is split into smaller pieces that each continue from the
// tile's next sample, so only the first submission after a jump in cost can overshoot.
#pragma once

#include <cstdint>
#include <deque>

namespace vkrt {

struct TileRect {
    std::uint32_t x = 0, y = 0, width = 0, height = 0;
    std::uint64_t pixels() const { return static_cast<std::uint64_t>(width) * height; }
};

struct Submission {
    TileRect tile;
    std::uint32_t firstSample = 0;
    std::uint32_t sampleCount = 0;  // sample passes = dispatches in this submission
};

struct TilingPolicy {
    double targetSeconds = 0.3;         // aim per submission (the brief: 0.25 - 0.5 s)
    std::uint64_t firstPixelSamples = 4096;  // the probe before anything was measured (64 workgroups)
    double maxGrowth = 4.0;             // a submission is at most this many times the previous one's work
    // Workgroups (8x8 blocks) per dispatch: maxComputeWorkGroupCount.x, and render.comp's
    // block = g * stride % workgroups must not overflow 32 bits, so at most 65535.
    std::uint32_t maxWorkgroups = 65535;
    // Tests: fixed tiles and passes instead of measured ones (0 = adaptive).
    std::uint32_t fixedTileWidth = 0, fixedTileHeight = 0;
    std::uint32_t fixedSamplesPerSubmission = 0;
};

class TilePlanner {
public:
    TilePlanner(std::uint32_t width, std::uint32_t height, std::uint32_t samples, const TilingPolicy& policy);

    bool done() const { return pieces_.empty() && cursorY_ >= height_; }
    // The next piece of work; only valid when !done().
    Submission next();
    // How long the submission returned by the last next() took; adapts the following sizes.
    void reportSeconds(double seconds);
    double fractionDone() const { return static_cast<double>(donePixelSamples_) / static_cast<double>(totalPixelSamples_); }

private:
    // Part of a tile whose pixels have all received samples [0, nextSample).
    struct Piece {
        TileRect tile;
        std::uint32_t nextSample = 0;
    };
    std::uint64_t budgetPixelSamples() const;
    TileRect newTile(std::uint64_t budget);
    void splitFront(std::uint64_t budget);

    std::uint32_t width_, height_, samples_;
    TilingPolicy policy_;
    std::deque<Piece> pieces_;  // the current tile's unfinished pieces, in order
    // Where the next tile starts, and the height of the band of rows it belongs to.
    std::uint32_t cursorX_ = 0, cursorY_ = 0, bandHeight_ = 0;
    // Measurements.
    double secondsPerPixelSample_ = 0.0;  // 0 until the first report
    std::uint64_t lastPixelSamples_ = 0;
    std::uint64_t donePixelSamples_ = 0;
    std::uint64_t totalPixelSamples_;
};

// A workgroup stride for `workgroups` blocks: coprime to it (so block = g * stride % workgroups,
// render.comp's mapping, is a permutation) and near workgroups / golden ratio, so that any run of
// consecutive workgroups - what lavapipe hands one thread - is spread evenly over the tile.
std::uint32_t interleaveStride(std::uint32_t workgroups);

}  // namespace vkrt
