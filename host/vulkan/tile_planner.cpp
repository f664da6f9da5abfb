#include "tile_planner.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace vkrt {

namespace {

constexpr std::uint32_t kBlock = 8;  // a workgroup covers 8x8 pixels (render.comp)

std::uint64_t workgroupsOf(std::uint32_t width, std::uint32_t height) {
    return static_cast<std::uint64_t>((width + kBlock - 1) / kBlock) * ((height + kBlock - 1) / kBlock);
}

std::uint32_t roundDownToBlock(std::uint64_t n) {
    return static_cast<std::uint32_t>(std::min<std::uint64_t>(n / kBlock * kBlock, 0xffffffffu));
}

}  // namespace

TilePlanner::TilePlanner(std::uint32_t width, std::uint32_t height, std::uint32_t samples, const TilingPolicy& policy)
    : width_(width), height_(height), samples_(samples), policy_(policy),
      totalPixelSamples_(static_cast<std::uint64_t>(width) * height * samples) {
    if (width == 0 || height == 0 || samples == 0) throw std::invalid_argument("TilePlanner: empty render");
    if (policy_.maxWorkgroups == 0) throw std::invalid_argument("TilePlanner: maxWorkgroups is 0");
    if ((policy_.fixedTileWidth == 0) != (policy_.fixedTileHeight == 0))
        throw std::invalid_argument("TilePlanner: a fixed tile needs both a width and a height");
    if (policy_.fixedTileWidth && workgroupsOf(policy_.fixedTileWidth, policy_.fixedTileHeight) > policy_.maxWorkgroups)
        throw std::invalid_argument("TilePlanner: a " + std::to_string(policy_.fixedTileWidth) + "x" +
                                    std::to_string(policy_.fixedTileHeight) + " tile needs more than " +
                                    std::to_string(policy_.maxWorkgroups) + " workgroups");
}

std::uint64_t TilePlanner::budgetPixelSamples() const {
    if (secondsPerPixelSample_ <= 0.0) return policy_.firstPixelSamples;
    double budget = policy_.targetSeconds / secondsPerPixelSample_;
    budget = std::min(budget, static_cast<double>(lastPixelSamples_) * policy_.maxGrowth);
    return std::max<std::uint64_t>(static_cast<std::uint64_t>(budget), kBlock * kBlock);
}

TileRect TilePlanner::newTile(std::uint64_t budget) {
    const std::uint32_t rowsLeft = height_ - cursorY_;
    const std::uint32_t columnsLeft = width_ - cursorX_;
    TileRect tile;
    if (policy_.fixedTileWidth) {
        if (cursorX_ == 0) bandHeight_ = std::min(policy_.fixedTileHeight, rowsLeft);
        tile = {cursorX_, cursorY_, std::min(policy_.fixedTileWidth, columnsLeft), bandHeight_};
    } else {
        // The tile holds at most `budget` pixels (a submission runs at least one sample pass).
        const std::uint64_t pixels = std::min<std::uint64_t>(budget, static_cast<std::uint64_t>(policy_.maxWorkgroups) * kBlock * kBlock);
        if (cursorX_ == 0) {
            const std::uint64_t fullRows = pixels / width_;
            if (fullRows >= rowsLeft) bandHeight_ = rowsLeft;
            else bandHeight_ = std::min(rowsLeft, std::max(kBlock, roundDownToBlock(fullRows)));
        }
        std::uint32_t tileWidth = columnsLeft;
        if (pixels / bandHeight_ < columnsLeft) tileWidth = std::clamp(roundDownToBlock(pixels / bandHeight_), kBlock, columnsLeft);
        // Partial blocks at the image edge can push the count over; narrow until it fits.
        while (workgroupsOf(tileWidth, bandHeight_) > policy_.maxWorkgroups && tileWidth > kBlock)
            tileWidth = std::max(kBlock, roundDownToBlock(tileWidth / 2));
        tile = {cursorX_, cursorY_, tileWidth, bandHeight_};
    }
    cursorX_ += tile.width;
    if (cursorX_ >= width_) {
        cursorX_ = 0;
        cursorY_ += bandHeight_;
    }
    return tile;
}

void TilePlanner::splitFront(std::uint64_t budget) {
    Piece& front = pieces_.front();
    TileRect& t = front.tile;
    if (t.pixels() <= budget) return;
    Piece rest = front;
    if (t.height > kBlock) {  // split off whole rows first: they keep the tile's full width
        const std::uint32_t rows = std::clamp(roundDownToBlock(budget / t.width), kBlock, t.height - 1);
        rest.tile.y = t.y + rows;
        rest.tile.height = t.height - rows;
        t.height = rows;
    } else if (t.width > kBlock) {
        const std::uint32_t columns = std::clamp(roundDownToBlock(budget / t.height), kBlock, t.width - 1);
        rest.tile.x = t.x + columns;
        rest.tile.width = t.width - columns;
        t.width = columns;
    } else {
        return;  // one block: the smallest piece of work there is
    }
    pieces_.insert(pieces_.begin() + 1, rest);
}

Submission TilePlanner::next() {
    const std::uint64_t budget = budgetPixelSamples();
    if (pieces_.empty()) pieces_.push_back({newTile(budget), 0});
    else if (!policy_.fixedTileWidth) splitFront(budget);
    Piece& piece = pieces_.front();
    std::uint32_t count = samples_ - piece.nextSample;
    if (policy_.fixedSamplesPerSubmission) count = std::min(count, policy_.fixedSamplesPerSubmission);
    else count = static_cast<std::uint32_t>(std::clamp<std::uint64_t>(budget / piece.tile.pixels(), 1, count));

    const Submission submission{piece.tile, piece.nextSample, count};
    lastPixelSamples_ = piece.tile.pixels() * count;
    piece.nextSample += count;
    if (piece.nextSample == samples_) pieces_.pop_front();
    return submission;
}

void TilePlanner::reportSeconds(double seconds) {
    donePixelSamples_ += lastPixelSamples_;
    // The latest measurement alone: neighbouring tiles cost alike, and an expensive region must
    // shrink the next submission at once rather than after an average catches up.
    if (lastPixelSamples_ > 0 && seconds > 0.0) secondsPerPixelSample_ = seconds / static_cast<double>(lastPixelSamples_);
}

std::uint32_t interleaveStride(std::uint32_t workgroups) {
    if (workgroups <= 2) return 1;
    constexpr double kInverseGolden = 0.6180339887498949;
    auto stride = static_cast<std::uint32_t>(static_cast<double>(workgroups) * kInverseGolden);
    stride = std::clamp<std::uint32_t>(stride, 1, workgroups - 1);
    while (std::gcd(stride, workgroups) != 1) ++stride;  // terminates: workgroups - 1 is coprime
    return stride;
}

}  // namespace vkrt
