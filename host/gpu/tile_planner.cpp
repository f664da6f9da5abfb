#include "tile_planner.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace vkrt {

namespace {

constexpr std::uint32_t kBlock = 8;                        // a workgroup covers 8x8 pixels (render.comp)
constexpr std::uint64_t kBlockPixels = kBlock * kBlock;

}  // namespace

std::vector<TileRect> planTiles(std::uint32_t width, std::uint32_t height, const TilingPolicy& policy) {
    std::vector<TileRect> tiles;
    if (policy.fixedTileWidth) {
        for (std::uint32_t y = 0; y < height; y += policy.fixedTileHeight)
            for (std::uint32_t x = 0; x < width; x += policy.fixedTileWidth)
                tiles.push_back({x, y, std::min(policy.fixedTileWidth, width - x), std::min(policy.fixedTileHeight, height - y)});
        return tiles;
    }
    const std::uint32_t blocksX = (width + kBlock - 1) / kBlock;
    if (blocksX > policy.maxWorkgroups)
        throw std::invalid_argument("an image " + std::to_string(width) + " pixels wide needs more than " +
                                    std::to_string(policy.maxWorkgroups) + " workgroups per row of blocks");
    const std::uint32_t bandRows = (policy.maxWorkgroups / blocksX) * kBlock;
    for (std::uint32_t y = 0; y < height; y += bandRows) tiles.push_back({0, y, width, std::min(bandRows, height - y)});
    return tiles;
}

TilePlanner::TilePlanner(std::uint32_t width, std::uint32_t height, std::uint32_t samples, const TilingPolicy& policy)
    : samples_(samples), policy_(policy) {
    if (width == 0 || height == 0 || samples == 0) throw std::invalid_argument("TilePlanner: empty render");
    if (policy_.maxWorkgroups == 0) throw std::invalid_argument("TilePlanner: maxWorkgroups is 0");
    if ((policy_.fixedTileWidth == 0) != (policy_.fixedTileHeight == 0))
        throw std::invalid_argument("TilePlanner: a fixed tile needs both a width and a height");
    tiles_ = planTiles(width, height, policy_);
    for (const TileRect& t : tiles_) {
        if (t.workgroups() > policy_.maxWorkgroups)
            throw std::invalid_argument("TilePlanner: a " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                                        " tile needs more than " + std::to_string(policy_.maxWorkgroups) + " workgroups");
        totalUnits_ += static_cast<std::uint64_t>(t.workgroups()) * samples;
    }
}

std::uint64_t TilePlanner::budgetPixelSamples() const {
    if (secondsPerUnit_ <= 0.0) return policy_.firstPixelSamples;
    double units = policy_.targetSeconds / secondsPerUnit_;
    units = std::min(units, static_cast<double>(lastUnits_) * policy_.maxGrowth);
    return std::max<std::uint64_t>(static_cast<std::uint64_t>(units), 1) * kBlockPixels;
}

Submission TilePlanner::next() {
    const TileRect& tile = tiles_[tile_];
    const std::uint32_t workgroups = tile.workgroups();
    const std::uint64_t budgetUnits = std::max<std::uint64_t>(budgetPixelSamples() / kBlockPixels, 1);

    Submission s{tile, workgroup_, 0, sample_, 1, tile_, false};
    const std::uint32_t left = workgroups - workgroup_;
    if (policy_.fixedWorkgroups) {
        s.workgroupCount = std::min(policy_.fixedWorkgroups, left);
    } else {
        // The rest of the pass in equal runs, so that no run is a small remainder.
        const std::uint64_t runs = (left + budgetUnits - 1) / budgetUnits;
        s.workgroupCount = static_cast<std::uint32_t>((left + runs - 1) / runs);
    }
    if (s.workgroupCount == workgroups) {  // a whole pass fits: take as many passes as the budget allows
        const std::uint32_t passesLeft = samples_ - sample_;
        s.sampleCount = policy_.fixedSamples ? std::min(policy_.fixedSamples, passesLeft)
                                             : static_cast<std::uint32_t>(std::clamp<std::uint64_t>(budgetUnits / workgroups, 1, passesLeft));
        for (const int stop : stops_)
            if (static_cast<std::uint32_t>(stop) > sample_) {
                s.sampleCount = std::min(s.sampleCount, static_cast<std::uint32_t>(stop) - sample_);
                break;
            }
    }

    lastUnits_ = static_cast<std::uint64_t>(s.workgroupCount) * s.sampleCount;
    workgroup_ += s.workgroupCount;
    if (workgroup_ == workgroups) {
        s.endsPasses = true;
        workgroup_ = 0;
        sample_ += s.sampleCount;
        if (sample_ == samples_) {
            sample_ = 0;
            ++tile_;
        }
    }
    return s;
}

void TilePlanner::reportSeconds(double seconds) {
    doneUnits_ += lastUnits_;
    // The latest measurement alone: every submission samples the whole tile evenly, so the
    // last one is the best predictor, and a change of scene cost is followed at once.
    if (lastUnits_ > 0 && seconds > 0.0) secondsPerUnit_ = seconds / static_cast<double>(lastUnits_);
}

std::uint32_t interleaveStride(std::uint32_t workgroups) {
    if (workgroups <= 2) return 1;
    constexpr double kInverseGolden = 0.6180339887498949;
    auto stride = static_cast<std::uint32_t>(static_cast<double>(workgroups) * kInverseGolden);
    stride = std::clamp<std::uint32_t>(stride, 1, workgroups - 1);
    while (std::gcd(stride, workgroups) != 1) ++stride;  // terminates: workgroups - 1 is coprime
    return stride;
}

gpu::PassParams passParams(const TileRect& tile, std::uint32_t firstSample, std::uint32_t count) {
    const std::uint32_t workgroups = tile.workgroups();
    gpu::PassParams p{};
    p.tile = glm::uvec4(tile.x, tile.y, tile.width, tile.height);
    p.pass = glm::uvec4(firstSample, interleaveStride(workgroups), workgroups, count);
    return p;
}

}  // namespace vkrt
