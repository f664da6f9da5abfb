// --exposure EV (issue 39): the written image is the render scaled by 2^EV, in every format and
// through every way out (a plain render, --part and merge), applied once. vkrt runs in-process
// (runVkrt) on the CPU reference, whose image is the same on every run, so images compare exactly.
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app.h"
#include "image.h"
#include "progressive_output.h"
#include "test_paths.h"

namespace vkrt {
namespace {

int vkrt(std::vector<std::string> args) {
    args.insert(args.begin(), "vkrt");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    return runVkrt(static_cast<int>(argv.size()), argv.data());
}

std::string softShadows() { return test::sourceDir() + "/scenes/soft_shadows.xml"; }
std::string out(const std::string& name) { return test::artifactDir() + "/exposure_" + name; }

const std::vector<std::string> kSmall{"-w", "24", "-h", "18", "-r", "4", "--device", "cpu", "-q"};

std::vector<std::string> renderArgs(const std::string& scene, std::vector<std::string> extra) {
    std::vector<std::string> args{scene};
    args.insert(args.end(), kSmall.begin(), kSmall.end());
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

struct Clipped {
    std::size_t white = 0;     // every channel clamped (written as 255): burnt out to white
    std::size_t anyChannel = 0;
};

Clipped clippedPixels(const Image& png) {
    Clipped c;
    for (const glm::vec3& p : png.pixels) {
        c.white += (p.r >= 1.0f && p.g >= 1.0f && p.b >= 1.0f) ? 1 : 0;
        c.anyChannel += (p.r >= 1.0f || p.g >= 1.0f || p.b >= 1.0f) ? 1 : 0;
    }
    return c;
}

TEST(Exposure, OneStopDoublesEveryLinearPixelExactly) {
    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"-o", out("ev0.exr")})), 0);
    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"--exposure", "1", "-o", out("ev1.exr")})), 0);
    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"--exposure", "-2", "-o", out("ev-2.exr")})), 0);
    const Image ev0 = readImage(out("ev0.exr")), ev1 = readImage(out("ev1.exr")), evMinus2 = readImage(out("ev-2.exr"));
    ASSERT_EQ(ev1.pixels.size(), ev0.pixels.size());
    std::size_t lit = 0, aboveOne = 0;
    for (std::size_t i = 0; i < ev0.pixels.size(); ++i) {
        // A power of two scales a float exactly: EXR is not clamped, so every pixel keeps the ratio.
        EXPECT_EQ(ev1.pixels[i], 2.0f * ev0.pixels[i]) << "pixel " << i;
        EXPECT_EQ(evMinus2.pixels[i], 0.25f * ev0.pixels[i]) << "pixel " << i;
        lit += ev0.pixels[i].g > 0.0f ? 1 : 0;
        aboveOne += ev1.pixels[i].g > 1.0f ? 1 : 0;
    }
    EXPECT_GT(lit, ev0.pixels.size() / 2) << "a mostly black image would hide a missing scale";
    EXPECT_GT(aboveOne, 0u) << "EXR keeps values above 1 (no clamp)";
}

// Each --progressive pass is written as the final image is, exposure included (the last pass is
// the final image itself, which the tests above cover).
TEST(Exposure, ProgressivePassesAreWrittenWithIt) {
    Image soFar(2, 1);
    soFar.pixels = {glm::vec3(0.25f, 0.5f, 3.0f), glm::vec3(0.0f, 1.0f, 0.125f)};
    ProgressiveOutput passes(out("pass.exr"), 16, -2.0f, /*quiet=*/true);
    passes.checkpoint(soFar, 4);
    const Image written = readImage(out("pass.exr"));
    ASSERT_EQ(written.pixels.size(), 2u);
    EXPECT_EQ(written.pixels[0], glm::vec3(0.0625f, 0.125f, 0.75f));
    EXPECT_EQ(written.pixels[1], glm::vec3(0.0f, 0.25f, 0.03125f));
}

// The 8-bit formats scale first and clamp after: a pixel written below 255 at EV 1 was c * 2,
// so its byte is int(2c * 255), which is 2 * int(c * 255) or one more.
TEST(Exposure, PngScalesBeforeTheClamp) {
    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"-o", out("ev0.png")})), 0);
    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"--exposure", "1", "-o", out("ev1.png")})), 0);
    const Image ev0 = readImage(out("ev0.png")), ev1 = readImage(out("ev1.png"));
    std::size_t checked = 0;
    for (std::size_t i = 0; i < ev0.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const int a = static_cast<int>(ev0.pixels[i][c] * 255.0f + 0.5f), b = static_cast<int>(ev1.pixels[i][c] * 255.0f + 0.5f);
            if (b == 255) continue;  // clamped
            EXPECT_TRUE(b == 2 * a || b == 2 * a + 1) << "pixel " << i << " channel " << c << ": " << a << " -> " << b;
            checked += a > 0 ? 1 : 0;
        }
    EXPECT_GT(checked, ev0.pixels.size()) << "too few unclamped, non-black values to judge";
}

// A part's EXR carries its exposure; merge copies it (no --exposure of its own), so the merged
// image is the whole render's at the same exposure, and parts of two exposures are refused.
TEST(Exposure, PartsCarryItAndMergeAppliesItOnce) {
    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"--exposure", "1", "-o", out("whole.exr")})), 0);
    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"--exposure", "1", "--part", "1/2", "-o", out("part1.exr")})), 0);
    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"--exposure", "1", "--part", "2/2", "-o", out("part2.exr")})), 0);
    ASSERT_EQ(vkrt({"merge", out("part1.exr"), out("part2.exr"), "-q", "-o", out("merged.exr")}), 0);
    EXPECT_EQ(readImage(out("merged.exr")).pixels, readImage(out("whole.exr")).pixels);

    ASSERT_EQ(vkrt(renderArgs(softShadows(), {"--part", "2/2", "-o", out("part2_ev0.exr")})), 0);
    testing::internal::CaptureStderr();
    EXPECT_EQ(vkrt({"merge", out("part1.exr"), out("part2_ev0.exr"), "-q", "-o", out("never.exr")}), 1);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("exposure 0"), std::string::npos) << err;
}

// The course's Cornell box with the specular shader burns a third of its pixels out to white at
// exposure 0 (64x64, 4 rpp: 1543 white of 4096, 3777 with some channel at 255); one stop down
// leaves 1131 white and 3640 (at 250x250, 16 rpp: 21094 -> 16699 white, 57815 -> 56661).
TEST(Exposure, OneStopDownClipsFewerPixelsOfTheBurntOutCornellBox) {
    const std::string scene = test::jsonSceneDir() + "/CornellBox_Specular.json";
    VKRT_SKIP_WITHOUT(scene);
    ASSERT_EQ(vkrt({scene, "-w", "64", "-h", "64", "-r", "4", "--device", "cpu", "-q", "-o", out("cornell_ev0.png")}), 0);
    ASSERT_EQ(vkrt({scene, "-w", "64", "-h", "64", "-r", "4", "--device", "cpu", "-q", "--exposure", "-1", "-o",
                    out("cornell_ev-1.png")}),
              0);
    const Clipped ev0 = clippedPixels(readImage(out("cornell_ev0.png")));
    const Clipped evMinus1 = clippedPixels(readImage(out("cornell_ev-1.png")));
    std::printf("CornellBox_Specular.json 64x64: white %zu -> %zu, a channel at 255 %zu -> %zu (exposure 0 -> -1)\n",
                ev0.white, evMinus1.white, ev0.anyChannel, evMinus1.anyChannel);
    EXPECT_GT(ev0.white, 64u * 64u / 4) << "the scene no longer burns out: this test needs another";
    EXPECT_LT(evMinus1.white * 5, ev0.white * 4) << "a fifth fewer white pixels at least";
    EXPECT_LT(evMinus1.anyChannel, ev0.anyChannel);
}

}  // namespace
}  // namespace vkrt
