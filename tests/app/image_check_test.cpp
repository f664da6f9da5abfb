// vkrt check (issue 39): the per-pixel test against vkrt's noise (image_check.h) on images with a
// known answer, each common mistake recognised on an image made wrong on purpose, and the command
// end to end on the instructor's reference renders (../shared/scenes/upstream/reference), which
// vkrt's render matches (tests/cpu/reference_render_test.cpp): correct, flipped, sRGB-encoded,
// without the reference look's background, without a light, without the environment map.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app.h"
#include "check_command.h"
#include "cpu_renderer.h"
#include "diagnostics.h"
#include "image.h"
#include "image_check.h"
#include "render_options.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

// An asymmetric, noise-free picture: no flip or rotation of it equals it.
CheckReference gradientReference(int w, int h) {
    CheckReference r;
    r.mean = Image(w, h);
    r.sampleVariance = Image(w, h);
    r.rpp = 64;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            r.mean.at(x, y) = glm::vec3(float(x) / float(w), float(y) / float(h), float(x * x + 3 * y) / float(w * w + 3 * h));
    return r;
}

// What an 8-bit file holds of a linear image: quantize8, read back as value/255.
Image eightBit(const Image& image) {
    Image out = image;
    for (glm::vec3& p : out.pixels)
        for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(quantize8(p[c])) / 255.0f;
    return out;
}

TEST(ImageCheck, ANoiseFreeReferenceMatchesItsOwn8BitFile) {
    const CheckReference r = gradientReference(64, 48);
    const PixelTestResult result = testPixels(eightBit(r.mean), r);
    EXPECT_EQ(result.passed, result.pixels);
    EXPECT_TRUE(result.same);
    EXPECT_LT(std::abs(result.meanSignedDifference), 1.0 / 255.0);  // truncation: at most one step darker
}

// The verdict needs >= 99% of pixels: 0.5% of pixels off by 10/255 is the same picture, 2% is not.
TEST(ImageCheck, TheVerdictNeedsNinetyNinePercentOfPixels) {
    const CheckReference r = gradientReference(100, 100);
    for (const auto& [wrongPixels, same] : {std::pair{50, true}, std::pair{200, false}}) {
        Image yours = r.mean;
        for (int k = 0; k < wrongPixels; ++k) yours.pixels[k * 37 % yours.pixels.size()].x += 10.0f / 255.0f;
        const PixelTestResult result = testPixels(yours, r);
        EXPECT_EQ(result.pixels - result.passed, static_cast<std::size_t>(wrongPixels));
        EXPECT_EQ(result.same, same) << wrongPixels << " wrong pixels";
    }
}

// Where vkrt's samples spread, a difference within zLimit standard errors (of one sample plus the
// reference mean) passes and one beyond fails; a flat area allows only the 2/255 slack.
TEST(ImageCheck, ADifferenceIsJudgedAgainstTheReferenceNoise) {
    CheckReference r = gradientReference(32, 32);
    for (glm::vec3& v : r.sampleVariance.pixels) v = glm::vec3(0.01f);  // one sample's sd 0.1
    r.rpp = 16;
    const double z = testPixels(r.mean, r).zLimit;
    ASSERT_GT(z, 4.0);  // Sidak over 3072 values at alpha 0.01
    const double standardError = 0.1 * std::sqrt(1.0 + 1.0 / 16.0);
    auto passedAt = [&](double steps) {
        Image yours = r.mean;
        yours.pixels[5].y += static_cast<float>(2.0 / 255.0 + steps * standardError);
        return testPixels(yours, r).passed == r.mean.pixels.size();
    };
    EXPECT_TRUE(passedAt(0.95 * z));
    EXPECT_FALSE(passedAt(1.05 * z));

    const CheckReference flat = gradientReference(32, 32);  // zero variance
    Image yours = flat.mean;
    yours.pixels[3].z += 1.9f / 255.0f;
    EXPECT_EQ(testPixels(yours, flat).passed, flat.mean.pixels.size());
    yours.pixels[3].z += 1.0f / 255.0f;  // 2.9/255
    EXPECT_EQ(testPixels(yours, flat).passed, flat.mean.pixels.size() - 1);
}

TEST(ImageCheck, TheReferenceIsClampedFor8BitImagesOnly) {
    CheckReference r = gradientReference(8, 8);
    for (glm::vec3& v : r.mean.pixels) v = glm::vec3(3.0f);  // burnt out: a PNG shows 255
    Image yours(8, 8);
    for (glm::vec3& v : yours.pixels) v = glm::vec3(1.0f);
    EXPECT_TRUE(testPixels(yours, r).same);
    PixelTestOptions linear;
    linear.clampReference = false;  // an EXR holds the radiance itself
    EXPECT_FALSE(testPixels(yours, r, linear).same);
}

TEST(ImageCheck, NaNNeverPasses) {
    const CheckReference r = gradientReference(8, 8);
    Image yours = r.mean;
    yours.pixels[0].x = NAN;
    EXPECT_EQ(testPixels(yours, r).passed, r.mean.pixels.size() - 1);
}

TEST(ImageCheck, TransformsAreTheirOwnInverses) {
    const Image a = gradientReference(7, 5).mean;
    const Image t = transposed(a);
    ASSERT_EQ(t.width, 5);
    ASSERT_EQ(t.height, 7);
    EXPECT_EQ(t.at(4, 6), a.at(6, 4));
    EXPECT_EQ(transposed(t).pixels, a.pixels);
    EXPECT_EQ(flippedVertically(a).at(2, 0), a.at(2, 4));
    EXPECT_EQ(flippedVertically(flippedVertically(a)).pixels, a.pixels);
    EXPECT_EQ(mirrored(a).at(0, 3), a.at(6, 3));
    EXPECT_EQ(mirrored(mirrored(a)).pixels, a.pixels);
}

// IEC 61966-2-1's values, and the two curves invert each other.
TEST(ImageCheck, SrgbCurves) {
    EXPECT_NEAR(srgbEncode(0.5f), 0.7354f, 1e-4f);
    EXPECT_NEAR(srgbEncode(0.002f), 0.02584f, 1e-5f);  // the linear toe
    EXPECT_NEAR(srgbDecode(0.7354f), 0.5f, 1e-4f);
    for (float v = 0.0f; v <= 1.0f; v += 0.01f) EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 1e-5f);
}

// Each mistake made on purpose: the image fails the plain test, passes as that mistake, and no
// other geometric mistake explains it (the diagnosis must name the right one).
TEST(ImageCheck, EachImageMistakeExplainsItsOwnImage) {
    const CheckReference r = gradientReference(40, 40);
    for (const Mistake& mistake : imageMistakes()) {
        SCOPED_TRACE(mistake.name);
        const Image yours = eightBit(mistake.apply(r).mean);
        EXPECT_FALSE(testPixels(yours, r).same);
        EXPECT_TRUE(testPixels(yours, mistake.apply(r)).same);
        if (mistake.name.find("half-pixel") != std::string::npos) continue;  // the four offsets overlap
        for (const Mistake& other : imageMistakes())
            if (other.name != mistake.name && other.name.find("half-pixel") == std::string::npos &&
                mistake.name.find("gamma") == std::string::npos && other.name.find("gamma") == std::string::npos)
                EXPECT_FALSE(testPixels(yours, other.apply(r)).same) << "also explained by " << other.name;
    }
}

TEST(ImageCheck, TheCommonFailingColourIsTheWrongBackground) {
    const CheckReference r = gradientReference(20, 20);
    Image yours = r.mean;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 8; ++x) yours.at(x, y) = glm::vec3(50.0f / 255.0f, 0.0f, 1.0f);
    const ColourCount c = commonFailingColour(yours, r);
    EXPECT_EQ(c.colour, glm::vec3(50.0f / 255.0f, 0.0f, 1.0f));
    EXPECT_GE(c.count, 150u);  // 160 pixels, a few of which happen to match
}

// ---- vkrt check end to end -------------------------------------------------------------------

struct CheckRun {
    int exitCode = 0;
    std::string out;
};

CheckRun check(const std::vector<std::string>& args) {
    std::vector<const char*> argv = {"vkrt", "check"};
    for (const std::string& a : args) argv.push_back(a.c_str());
    argv.push_back("-q");
    testing::internal::CaptureStdout();
    const int code = runVkrt(static_cast<int>(argv.size()), argv.data());
    return {code, testing::internal::GetCapturedStdout()};
}

std::string inArtifacts(const std::string& name) { return artifactDir() + "/check_" + name; }

class CheckCommand : public testing::Test {
protected:
    void SetUp() override {
        VKRT_SKIP_WITHOUT(upstreamDir() + "/reference/PhongExp.png");
        instructor = readImage(upstreamDir() + "/reference/PhongExp.png");
        scene = upstreamDir() + "/PhongExp.xml";
    }
    Image instructor;
    std::string scene;
};

// The instructor's image of PhongExp.xml is vkrt's picture under --look reference (measured:
// 99.98% of pixels pass), and the reference and difference map land beside it.
TEST_F(CheckCommand, TheInstructorsRenderIsTheSamePicture) {
    const std::string mine = inArtifacts("PhongExp.png");
    writeImage(instructor, mine);
    const CheckRun run = check({scene, mine, "--look", "reference"});
    EXPECT_EQ(run.exitCode, kExitSamePicture) << run.out;
    EXPECT_NE(run.out.find("verdict          SAME"), std::string::npos) << run.out;
    EXPECT_EQ(readImage(inArtifacts("PhongExp_vkrt_reference.png")).width, instructor.width);
    EXPECT_GT(readImage(inArtifacts("PhongExp_vkrt_diff.png")).height, instructor.height);  // with its legend
}

TEST_F(CheckCommand, AFlippedImageIsDifferentAndSaysSo) {
    const std::string mine = inArtifacts("PhongExp_flipped.png");
    writeImage(flippedVertically(instructor), mine);
    const CheckRun run = check({scene, mine, "--look", "reference"});
    EXPECT_EQ(run.exitCode, kExitDifferentPicture) << run.out;
    EXPECT_NE(run.out.find("likely mistake   flipped vertically"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("verdict          DIFFERENT"), std::string::npos) << run.out;
}

TEST_F(CheckCommand, AnSrgbEncodedImageIsRecognised) {
    Image encoded = instructor;
    for (glm::vec3& p : encoded.pixels)
        for (int c = 0; c < 3; ++c) p[c] = srgbEncode(p[c]);
    const std::string mine = inArtifacts("PhongExp_srgb.png");
    writeImage(encoded, mine);
    const CheckRun run = check({scene, mine, "--look", "reference"});
    EXPECT_EQ(run.exitCode, kExitDifferentPicture) << run.out;
    EXPECT_NE(run.out.find("likely mistake   sRGB gamma applied"), std::string::npos) << run.out;
}

// Without --look reference the scene's black background is expected: the diagnosis names the
// instructor's grey and the option that renders it.
TEST_F(CheckCommand, TheWrongBackgroundIsNamedWithItsColour) {
    const std::string mine = inArtifacts("PhongExp_grey.png");
    writeImage(instructor, mine);
    const CheckRun run = check({scene, mine});
    EXPECT_EQ(run.exitCode, kExitDifferentPicture) << run.out;
    EXPECT_NE(run.out.find("likely mistake   background colour"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("(50, 50, 50)/255"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("--look reference"), std::string::npos) << run.out;
}

// mirrorTest2.xml names an environment map; the instructor's render shows the grey background.
TEST_F(CheckCommand, AMissingEnvironmentMapIsNamed) {
    VKRT_SKIP_WITHOUT(upstreamDir() + "/reference/mirrorTest2.png");
    const std::string mine = inArtifacts("mirrorTest2.png");
    writeImage(readImage(upstreamDir() + "/reference/mirrorTest2.png"), mine);
    const CheckRun run = check({upstreamDir() + "/mirrorTest2.xml", mine});
    EXPECT_EQ(run.exitCode, kExitDifferentPicture) << run.out;
    EXPECT_NE(run.out.find("likely mistake   no environment map"), std::string::npos) << run.out;
}

// boxSphereTest.xml has two point lights; "yours" is the CPU reference's render without the second.
TEST_F(CheckCommand, AMissingLightIsNamed) {
    Diagnostics diagnostics;
    Scene box = loadScene(upstreamDir() + "/boxSphereTest.xml", LoadOptions{}, diagnostics);
    ASSERT_EQ(box.lights.size(), 2u);
    box.lights.pop_back();
    RenderOptions options;
    applyReferenceLook(options);
    const std::string mine = inArtifacts("boxSphereTest_one_light.png");
    writeImage(renderCpu(box, prepareCpuScene(box), options), mine);
    const CheckRun run = check({upstreamDir() + "/boxSphereTest.xml", mine, "--look", "reference"});
    EXPECT_EQ(run.exitCode, kExitDifferentPicture) << run.out;
    EXPECT_NE(run.out.find("likely mistake   light 2 of 2 missing"), std::string::npos) << run.out;
}

// An image made at --exposure 1 is the same picture when check is told so, and not otherwise.
TEST_F(CheckCommand, ExposureScalesTheReference) {
    Image doubled = instructor;
    for (glm::vec3& p : doubled.pixels) p = glm::min(2.0f * p, glm::vec3(1.0f));
    const std::string mine = inArtifacts("PhongExp_ev1.png");
    writeImage(doubled, mine);
    const CheckRun told = check({scene, mine, "--look", "reference", "--exposure", "1"});
    EXPECT_EQ(told.exitCode, kExitSamePicture) << told.out;
    const CheckRun notTold = check({scene, mine, "--look", "reference"});
    EXPECT_EQ(notTold.exitCode, kExitDifferentPicture) << notTold.out;
}

// The old course code's ambient term lights what the course's shading leaves black: no mistake
// explains it, and check says where the difference is.
TEST_F(CheckCommand, LightWhereVkrtIsBlackIsCalledAnAmbientTerm) {
    Image ambient = instructor;
    for (glm::vec3& p : ambient.pixels)
        if (glm::all(glm::lessThan(p, glm::vec3(0.5f / 255.0f)))) p = glm::vec3(0.1f);
    const std::string mine = inArtifacts("PhongExp_ambient.png");
    writeImage(ambient, mine);
    const CheckRun run = check({scene, mine, "--look", "reference"});
    EXPECT_EQ(run.exitCode, kExitDifferentPicture) << run.out;
    EXPECT_NE(run.out.find("none of the"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("an ambient term?"), std::string::npos) << run.out;
}

TEST_F(CheckCommand, RefusesASizeAndAGpu) {
    const std::string mine = inArtifacts("PhongExp.png");
    writeImage(instructor, mine);
    testing::internal::CaptureStderr();
    EXPECT_EQ(check({scene, mine, "-w", "100"}).exitCode, 2);
    EXPECT_EQ(check({scene, mine, "--device", "gpu"}).exitCode, 2);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("check renders at your image's size"), std::string::npos) << err;
    EXPECT_NE(err.find("check renders its reference on the CPU"), std::string::npos) << err;
}

TEST_F(CheckCommand, AMissingImageIsAnErrorNamingIt) {
    testing::internal::CaptureStderr();
    EXPECT_EQ(check({scene, inArtifacts("no_such.png")}).exitCode, 1);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("no_such.png"), std::string::npos) << err;
}

}  // namespace
}  // namespace vkrt::test
