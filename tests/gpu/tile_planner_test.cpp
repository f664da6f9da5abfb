// The tile planner (tile_planner.h) against a simulated device: every 8x8 block gets every sample
// once and in order, submissions stay near their target time, large images split into bands.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <numeric>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "tile_planner.h"

namespace vkrt {
namespace {

// The 8x8 blocks a submission covers: render.comp's mapping of its workgroups.
std::vector<glm::uvec2> blocksOf(const Submission& s) {
    const gpu::PassParams p = passParams(s.tile, s.firstSample);
    const std::uint32_t blocksX = (s.tile.width + 7) / 8;
    std::vector<glm::uvec2> blocks;
    for (std::uint32_t g = s.firstWorkgroup; g < s.firstWorkgroup + s.workgroupCount; ++g) {
        const std::uint32_t block = (g * p.pass.y) % p.pass.z;  // 32-bit, as on the device
        blocks.emplace_back(s.tile.x / 8 + block % blocksX, s.tile.y / 8 + block / blocksX);
    }
    return blocks;
}

// Runs a planner to the end with a simulated device taking `costOf(submission)` seconds,
// checking that every 8x8 block of the image gets every sample exactly once and in order;
// returns the submissions.
template <class Cost>
std::vector<Submission> simulate(std::uint32_t width, std::uint32_t height, std::uint32_t samples, const TilingPolicy& policy,
                                 Cost costOf) {
    TilePlanner planner(width, height, samples, policy);
    const std::uint32_t blocksX = (width + 7) / 8, blocksY = (height + 7) / 8;
    std::vector<std::uint32_t> nextSample(static_cast<std::size_t>(blocksX) * blocksY, 0);
    std::vector<Submission> all;
    while (!planner.done()) {
        const Submission s = planner.next();
        EXPECT_GT(s.sampleCount, 0u);
        EXPECT_GT(s.workgroupCount, 0u);
        EXPECT_LE(s.firstWorkgroup + s.workgroupCount, s.tile.workgroups());
        EXPECT_LE(s.firstWorkgroup + s.workgroupCount, policy.maxWorkgroups);  // vkCmdDispatchBase's limit
        EXPECT_LE(s.tile.x + s.tile.width, width);
        EXPECT_LE(s.tile.y + s.tile.height, height);
        EXPECT_TRUE(s.sampleCount == 1 || s.workgroupCount == s.tile.workgroups()) << "several passes over part of a tile";
        for (const glm::uvec2 b : blocksOf(s)) {
            std::uint32_t& next = nextSample[static_cast<std::size_t>(b.y) * blocksX + b.x];
            EXPECT_EQ(next, s.firstSample) << "block " << b.x << "," << b.y << " got samples out of order";
            next = s.firstSample + s.sampleCount;
        }
        planner.reportSeconds(costOf(s));
        all.push_back(s);
        if (all.size() > 1000000) {
            ADD_FAILURE() << "planner does not finish";
            break;
        }
    }
    for (std::uint32_t n : nextSample) EXPECT_EQ(n, samples);
    EXPECT_DOUBLE_EQ(planner.fractionDone(), 1.0);
    return all;
}

double uniformCost(const Submission& s, double perBlockSample) {
    return perBlockSample * s.workgroupCount * s.sampleCount;
}

TEST(TilePlanner, CoversEveryBlockSampleOnceInOrder) {
    for (auto [w, h, spp] : {std::tuple{1u, 1u, 1u}, {250u, 250u, 16u}, {70u, 45u, 5u}, {1000u, 3u, 2u}, {3u, 1000u, 7u}}) {
        SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + "x" + std::to_string(spp));
        const TilingPolicy adaptive;
        simulate(w, h, spp, adaptive, [](const Submission& s) { return uniformCost(s, 1e-6); });
        simulate(w, h, spp, adaptive, [](const Submission& s) { return uniformCost(s, 1e-1); });
        TilingPolicy fixed;
        fixed.fixedTileWidth = 16;
        fixed.fixedTileHeight = 24;
        fixed.fixedWorkgroups = 5;
        simulate(w, h, spp, fixed, [](const Submission&) { return 0.01; });
        TilingPolicy passes;
        passes.fixedSamples = 3;
        simulate(w, h, spp, passes, [](const Submission&) { return 0.01; });
    }
}

TEST(TilePlanner, FixedPolicyGivesTheAskedSubmissions) {
    TilingPolicy fixed;
    fixed.fixedTileWidth = 16;
    fixed.fixedTileHeight = 8;
    fixed.fixedWorkgroups = 1;
    fixed.fixedSamples = 1;
    const auto all = simulate(40, 10, 3, fixed, [](const Submission&) { return 0.01; });
    // 3 x 2 tiles of 2, 2, 1 (top) and 2, 2, 1 (bottom) workgroups, one workgroup and one pass each.
    ASSERT_EQ(all.size(), (2u + 2u + 1u) * 2u * 3u);
    EXPECT_EQ(all[0].tile.width, 16u);
    EXPECT_EQ(all[1].firstWorkgroup, 1u);
    EXPECT_EQ(all[2].firstSample, 1u);
    EXPECT_EQ(all[12].tile.width, 8u);
    EXPECT_EQ(all[15].tile.y, 8u);
    EXPECT_EQ(all[15].tile.height, 2u);
}

// A progressive render's stops (RenderOptions::checkpoints): however many passes the budget would
// take at once, no submission runs past a stop, every stop of every tile ends a submission that
// says it completes the tile's passes (endsPasses), and the tiles are named in order.
TEST(TilePlanner, SubmissionsEndOnEveryStopOfEveryTile) {
    for (const bool tiled : {false, true}) {
        TilingPolicy policy;
        if (tiled) {
            policy.fixedTileWidth = 24;
            policy.fixedTileHeight = 16;
        }
        TilePlanner planner(48, 32, 10, policy);
        planner.stopAtPasses({3, 6, 10});
        std::vector<std::vector<std::uint32_t>> ended(planner.tiles().size());
        std::size_t lastTile = 0;
        while (!planner.done()) {
            const Submission s = planner.next();
            EXPECT_GE(s.tileIndex, lastTile);
            lastTile = s.tileIndex;
            for (const std::uint32_t stop : {3u, 6u})
                EXPECT_FALSE(s.firstSample < stop && s.firstSample + s.sampleCount > stop) << "crosses stop " << stop;
            if (s.endsPasses) ended[s.tileIndex].push_back(s.firstSample + s.sampleCount);
            planner.reportSeconds(1e-9);  // so cheap that the budget would take every pass at once
        }
        for (const std::vector<std::uint32_t>& ends : ended) {
            for (const std::uint32_t stop : {3u, 6u, 10u})
                EXPECT_NE(std::find(ends.begin(), ends.end(), stop), ends.end()) << "no submission ends at " << stop;
        }
    }
}

// With a uniform cost the planner learns it from the first probe: no later submission may
// exceed the target, and once grown they should use at least half of it.
TEST(TilePlanner, SubmissionsStayNearTheTarget) {
    const TilingPolicy policy;  // 0.3 s
    const double cost = 1e-4;   // seconds per block-sample: 3000 per target
    const auto all = simulate(1024, 768, 64, policy, [&](const Submission& s) { return uniformCost(s, cost); });
    int full = 0;
    for (std::size_t i = 1; i < all.size(); ++i) {
        EXPECT_LE(uniformCost(all[i], cost), policy.targetSeconds * 1.0001) << "submission " << i;
        if (uniformCost(all[i], cost) >= policy.targetSeconds / 2) ++full;
    }
    EXPECT_GT(full, static_cast<int>(all.size()) * 9 / 10) << all.size() << " submissions";
}

// All the cost in a corner: a tenth of the image 100x more expensive than the rest. Spatial
// tiles sized from the cheap part would overshoot ~10x on reaching the corner; interleaved
// workgroup runs sample the corner in proportion from the first probe on.
TEST(TilePlanner, AnExpensiveCornerDoesNotMakeSubmissionsOvershoot) {
    const TilingPolicy policy;
    const std::uint32_t width = 640, height = 480;
    auto seconds = [&](const Submission& s) {
        double total = 0.0;
        for (const glm::uvec2 b : blocksOf(s)) total += (b.x < width / 8 / 4 && b.y < height / 8 * 4 / 10) ? 1e-3 : 1e-5;
        return total * s.sampleCount;
    };
    const auto all = simulate(width, height, 16, policy, seconds);
    double worst = 0.0;
    for (std::size_t i = 1; i < all.size(); ++i) worst = std::max(worst, seconds(all[i]));
    std::cout << all.size() << " submissions, longest " << worst << " s for a target of " << policy.targetSeconds << " s\n";
    // A run of n consecutive workgroups holds the corner's share of blocks to within a few blocks
    // (a golden-ratio sequence), so the estimate is off by a few percent at most.
    EXPECT_LE(worst, policy.targetSeconds * 1.2);
}

TEST(TilePlanner, LargeImagesAreSplitIntoBandsOfAtMostMaxWorkgroups) {
    TilingPolicy policy;
    policy.maxWorkgroups = 1000;
    const std::vector<TileRect> tiles = planTiles(800, 1000, policy);  // 100 blocks per row: 80 rows per band
    ASSERT_EQ(tiles.size(), 13u);
    EXPECT_EQ(tiles[0].height, 80u);
    EXPECT_EQ(tiles[12].height, 40u);
    for (const TileRect& t : tiles) EXPECT_LE(t.workgroups(), 1000u);
    simulate(800, 1000, 2, policy, [](const Submission& s) { return uniformCost(s, 1e-9); });
    EXPECT_EQ(planTiles(250, 250, TilingPolicy{}).size(), 1u);
}

TEST(InterleaveStride, IsAPermutationSpreadOverTheTile) {
    for (std::uint32_t n = 1; n <= 3000; ++n) {
        const std::uint32_t stride = interleaveStride(n);
        ASSERT_EQ(std::gcd(stride, n), 1u) << n;
        ASSERT_LT(stride, std::max(n, 2u)) << n;
    }
    // lavapipe gives each of its threads a contiguous run of workgroups: with 2 threads, the
    // first half of the workgroups must cover both halves of the tile about equally.
    const std::uint32_t n = 1000, stride = interleaveStride(n);
    std::vector<bool> seen(n, false);
    int firstHalfInLowerHalf = 0;
    for (std::uint32_t g = 0; g < n; ++g) {
        const std::uint32_t block = static_cast<std::uint32_t>((static_cast<std::uint64_t>(g) * stride) % n);
        EXPECT_FALSE(seen[block]);
        seen[block] = true;
        if (g < n / 2 && block < n / 2) ++firstHalfInLowerHalf;
    }
    EXPECT_NEAR(firstHalfInLowerHalf, 250, 25);
}

}  // namespace
}  // namespace vkrt
