// Where float intersection stops working, on both devices, and that the loader warns exactly
// there (host/scene/geometry_extent.h, issue 22). Each scene is a file loaded as `vkrt` loads it.
//   - reach: an object 0.2 rad wide, lit from the eye, at distance d renders the image it renders
//     at d = 1 (the scene is the same up to scale) while d is within the limit, and nothing at all
//     once products of its coordinates overflow: triangles at 1e12 vs 1e14, spheres at 1e17 vs
//     1e20, a point light at 1e17 vs 1e20 (compared with one at 1e5);
//   - span: one ground triangle of half-width W seen from 1 above renders the W = 10 image up to
//     W = 1e6 and is broken at W = 1e7 (hits computed to 2^-24 W ~ 0.6 units).
// The loader warns for the failing cases and not for the working ones. Before the fix of
// surface.cpp's normal (unitVector), the CPU rendered triangles of edges beyond ~1e9 black.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "both_paths.h"
#include "diagnostics.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::stability {
namespace {

namespace fs = std::filesystem;

const glm::vec3 kBackground(0.0f, 0.0f, 1.0f);

std::string num(double x) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", x);
    return text;
}

std::string sceneText(const std::string& camera, const std::string& lightPosition, const std::string& shape) {
    return "<scene><sceneParameters><bgColor>0 0 1</bgColor></sceneParameters>\n" + camera +
           "\n<light type=\"point\"><position>" + lightPosition + "</position><intensity>1 1 1</intensity></light>\n"
           "<shader name=\"w\" type=\"Lambertian\"><diffuse>1 0.5 0</diffuse></shader>\n" + shape + "\n</scene>\n";
}

const std::string kLookingDownZ =
    "<camera name=\"c\" type=\"perspective\"><position>0 0 0</position><viewDir>0 0 -1</viewDir>"
    "<focalLength>1</focalLength><imagePlaneWidth>1</imagePlaneWidth></camera>";

std::string objectAt(const std::string& kind, double d) {
    const double r = 0.2 * d;
    if (kind == "sphere")
        return "<shape name=\"far\" type=\"sphere\"><shader ref=\"w\"/><center>0 0 " + num(-d) + "</center><radius>" + num(r) + "</radius></shape>";
    return "<shape name=\"far\" type=\"triangle\"><shader ref=\"w\"/><v0>" + num(-r) + " " + num(-r) + " " + num(-d) + "</v0><v1>" + num(r) +
           " " + num(-r) + " " + num(-d) + "</v1><v2>0 " + num(r) + " " + num(-d) + "</v2></shape>";
}

struct Loaded {
    BothImages images;
    std::size_t warnings = 0;
    std::string firstWarning;
};

Loaded renderFile(const std::string& name, const std::string& text) {
    const fs::path dir = fs::path(test::artifactDir()) / "extent_limits";
    fs::create_directories(dir);
    const fs::path path = dir / (name + ".xml");
    std::ofstream(path) << text;
    Diagnostics diagnostics;
    const Scene scene = loadScene(path.string(), LoadOptions{false, /*localOrigin=*/true}, diagnostics);
    Loaded out;
    out.warnings = diagnostics.warnings().size();
    if (out.warnings > 0) out.firstWarning = diagnostics.messages()[0];
    out.images = renderBoth(scene, smallOptions(24, 24, 1));
    return out;
}

std::size_t notBackground(const Image& image) {
    std::size_t n = 0;
    for (const glm::vec3& p : image.pixels) n += p != kBackground;
    return n;
}

void expectSameImage(const BothImages& got, const BothImages& expected, const std::string& what) {
    const Distance cpu = distance(got.cpu, expected.cpu), gpu = distance(got.gpu, expected.gpu);
    recordRow(what, cpu, gpu, distance(got.gpu, got.cpu));
    EXPECT_TRUE(agrees(cpu)) << what << " CPU: " << cpu.describe();
    EXPECT_TRUE(agrees(gpu)) << what << " GPU: " << gpu.describe();
}

TEST(ExtentLimits, ObjectsRenderUpToTheirReachAndVanishBeyondItWithAWarning) {
    for (const std::string kind : {"triangle", "sphere"}) {
        SCOPED_TRACE(kind);
        const double within = kind == "triangle" ? 1e12 : 1e17, beyond = kind == "triangle" ? 1e14 : 1e20;
        const Loaded unit = renderFile(kind + "_1", sceneText(kLookingDownZ, "0 0 0", objectAt(kind, 1.0)));
        ASSERT_GT(notBackground(unit.images.cpu), 30u);  // the object covers a part of the view (44 of 576 pixels for the triangle)
        const Loaded near = renderFile(kind + "_within", sceneText(kLookingDownZ, "0 0 0", objectAt(kind, within)));
        EXPECT_EQ(near.warnings, 0u) << near.firstWarning;
        expectSameImage(near.images, unit.images, kind + " at " + num(within) + " vs at 1");
        const Loaded far = renderFile(kind + "_beyond", sceneText(kLookingDownZ, "0 0 0", objectAt(kind, beyond)));
        EXPECT_EQ(far.warnings, 1u);
        EXPECT_NE(far.firstWarning.find("shape 'far'"), std::string::npos) << far.firstWarning;
        EXPECT_EQ(notBackground(far.images.cpu), 0u) << "the limit moved: the CPU now renders a " << kind << " at " << beyond;
        EXPECT_EQ(notBackground(far.images.gpu), 0u) << "the limit moved: the GPU now renders a " << kind << " at " << beyond;
    }
}

TEST(ExtentLimits, ALightLightsUpToItsReachAndNothingBeyondItWithAWarning) {
    const std::string ball = objectAt("sphere", 5.0);
    // From 1e5 on, the light's direction at the ball (5 from the eye) is +z within 1e-4 rad.
    const Loaded close = renderFile("light_1e5", sceneText(kLookingDownZ, "0 0 1e5", ball));
    const Loaded within = renderFile("light_within", sceneText(kLookingDownZ, "0 0 1e17", ball));
    EXPECT_EQ(within.warnings, 0u) << within.firstWarning;
    expectSameImage(within.images, close.images, "point light at 1e17 vs at 1e5");
    const Loaded beyond = renderFile("light_beyond", sceneText(kLookingDownZ, "0 0 1e20", ball));
    ASSERT_EQ(beyond.warnings, 1u);
    EXPECT_NE(beyond.firstWarning.find("may light nothing"), std::string::npos) << beyond.firstWarning;
    for (const Image* image : {&beyond.images.cpu, &beyond.images.gpu})
        for (const glm::vec3& p : image->pixels) EXPECT_TRUE(p == kBackground || p == glm::vec3(0.0f)) << "the limit moved";
}

TEST(ExtentLimits, AGroundTriangleHoldsUpToAMillionTimesTheCameraHeightWithoutAWarning) {
    const std::string camera =
        "<camera name=\"c\" type=\"perspective\"><position>0 1 0</position><viewDir>0 -1 -0.5</viewDir>"
        "<focalLength>1</focalLength><imagePlaneWidth>1</imagePlaneWidth></camera>";
    const auto ground = [](double w) {
        return "<shape name=\"ground\" type=\"triangle\"><shader ref=\"w\"/><v0>" + num(-w) + " 0 " + num(w) + "</v0><v1>" + num(w) + " 0 " +
               num(w) + "</v1><v2>0 0 " + num(-w) + "</v2></shape>";
    };
    const Loaded small = renderFile("ground_10", sceneText(camera, "0 10 0", ground(10.0)));
    const Loaded wide = renderFile("ground_1e6", sceneText(camera, "0 10 0", ground(1e6)));
    EXPECT_EQ(wide.warnings, 0u) << wide.firstWarning;
    expectSameImage(wide.images, small.images, "ground triangle W=1e6 vs W=10");
    const Loaded huge = renderFile("ground_1e7", sceneText(camera, "0 10 0", ground(1e7)));
    ASSERT_EQ(huge.warnings, 1u);
    EXPECT_NE(huge.firstWarning.find("split it into smaller triangles"), std::string::npos) << huge.firstWarning;
    const Distance broken = distance(huge.images.cpu, small.images.cpu);
    recordRow("ground triangle W=1e7 vs W=10 (warned)", broken, distance(huge.images.gpu, small.images.gpu), distance(huge.images.gpu, huge.images.cpu));
    EXPECT_FALSE(agrees(broken)) << "the limit moved: W=1e7 now renders right on the CPU: " << broken.describe();
    EXPECT_FALSE(agrees(distance(huge.images.gpu, small.images.gpu))) << "the limit moved: W=1e7 now renders right on the GPU";
}

}  // namespace
}  // namespace vkrt::stability
