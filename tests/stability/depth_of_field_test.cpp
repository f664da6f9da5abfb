// Depth of field (issue 21): the thin lens of docs/RENDERING.md §1 on both devices, checked against
// what a thin lens must do, not against the other path only:
//   - a surface lying on the focus plane is sharp: every lens ray of a pixel meets it at the pinhole
//     ray's point, so its image equals the pinhole image (within 1/255 away from tile edges);
//   - a small sphere off the focus plane spreads into a disc whose diameter is the circle of
//     confusion A |d - D| / d, projected to pixels (within 5%);
//   - the general kernel (lens code compiled in) renders a pinhole camera bit for bit as the
//     specialised one (no lens code) does;
//   - the two devices agree on a defocused scene by the project's rule.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "both_paths.h"
#include "gpu_environment.h"
#include "image_compare.h"
#include "scene_building.h"

namespace vkrt::stability {
namespace {

// Perspective camera at the origin looking down -z: focal length 1, image plane 0.5 wide.
Camera lensCamera(float focusDistance, float aperture) {
    Camera c = perspective({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, 1.0f, 0.5f);
    c.focusDistance = focusDistance;
    c.aperture = aperture;
    return c;
}

// A wall of 4x4 differently coloured tiles whose front faces lie exactly on z = -D, lit by a point
// light at the eye: Lambertian shading depends only on the hit point, not on the lens point.
Scene tiledWall(float focusDistance, float aperture) {
    Scene scene;
    scene.path = "tiles on the focus plane (built in code)";
    scene.cameras.push_back(lensCamera(focusDistance, aperture));
    scene.lights.push_back(pointLight({0.0f, 0.0f, 0.0f}, glm::vec3(1.0f)));
    const float tile = 0.25f * focusDistance * 0.5f;  // 4 tiles span the view's width at D (0.5 D)
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const glm::vec3 colour(0.2f + 0.2f * i, 0.9f - 0.2f * j, (i + j) % 2 ? 0.8f : 0.1f);
            const int shader = add(scene, lambertian(colour));
            const float x0 = (i - 2) * tile, y0 = (j - 2) * tile;
            scene.shapes.push_back(box({x0, y0, -focusDistance - 1.0f}, {x0 + tile, y0 + tile, -focusDistance}, shader));
        }
    return scene;
}

TEST(DepthOfField, ASurfaceOnTheFocusPlaneIsSharp) {
    const float D = 3.0f;
    const RenderOptions options = smallOptions(64, 64, 16);
    const BothImages pinhole = renderBoth(tiledWall(D, 0.0f), options);
    const BothImages lens = renderBoth(tiledWall(D, 0.8f), options);  // a lens 0.8 wide: blur of ~55 px off the plane
    // Pixels within one pixel of a tile edge are left out: which tile a lens ray at the edge meets is
    // float rounding (the lens rays reach the same point through different arithmetic).
    const auto nearEdge = [](int p) { return p % 16 == 0 || p % 16 == 15; };  // 16 px per tile
    for (const auto& [name, a, b] : {std::tuple{"CPU", &pinhole.cpu, &lens.cpu}, std::tuple{"GPU", &pinhole.gpu, &lens.gpu}}) {
        int checked = 0, off = 0;
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x) {
                if (nearEdge(x) || nearEdge(y)) continue;
                ++checked;
                const glm::vec3 d = glm::abs(a->at(x, y) - b->at(x, y));
                off += std::max({d.x, d.y, d.z}) > 1.0f / 255.0f;
            }
        EXPECT_GT(checked, 2500);
        EXPECT_EQ(off, 0) << name << ": " << off << " of " << checked << " pixels on the focus plane changed with the aperture";
    }
    // And the lens is really there: the same wall 1 unit behind the focus plane blurs its edges.
    Scene behind = tiledWall(D, 0.8f);
    behind.cameras[0].focusDistance = D - 1.0f;
    const BothImages blurred = renderBoth(behind, options);
    EXPECT_GT(distance(blurred.cpu, pinhole.cpu).maxSteps, 20);
}

// A small white sphere on the axis at distance d, the focus at D, black background.
Scene sphereOffFocus(float d, float D, float aperture, float radius) {
    Scene scene;
    scene.path = "a sphere off the focus plane (built in code)";
    scene.cameras.push_back(lensCamera(D, aperture));
    scene.lights.push_back(pointLight({0.0f, 0.0f, 0.0f}, glm::vec3(1.0f)));
    scene.shapes.push_back(sphere({0.0f, 0.0f, -d}, radius, add(scene, lambertian(glm::vec3(1.0f)))));
    return scene;
}

// The blur disc's diameter in pixels from energy conservation: the image is the sphere's sharp
// image convolved with a uniform disc of area c, so (total energy) / (plateau level) = c exactly,
// whatever the sphere's own image looks like, as long as it fits inside the disc.
double discDiameter(const Image& image, double expectedDiameter) {
    double energy = 0.0, plateau = 0.0;
    int plateauPixels = 0;
    const double c = 0.5 * image.width;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double v = image.at(x, y).g;
            energy += v;
            if (std::hypot(x + 0.5 - c, y + 0.5 - c) < 0.3 * expectedDiameter) {
                plateau += v;
                ++plateauPixels;
            }
        }
    plateau /= plateauPixels;
    return 2.0 * std::sqrt(energy / plateau / 3.14159265358979);
}

// Issue 38: a focus distance of 1e20 or more overflowed the lens ray's squared length, and both
// devices rendered background only. Focused that far, a lens 0.001 wide blurs a sphere 5 away by
// A * 128 / d = 0.03 px: the image is the pinhole's, within the agreement rule, on both devices,
// perspective and orthographic.
TEST(DepthOfField, AFocusDistanceAtTheEndOfFloatIsNotABackgroundImage) {
    const RenderOptions options = smallOptions(32, 32, 4);
    for (const bool orthographic : {false, true}) {
        Scene pinholeScene = sphereOffFocus(5.0f, 0.0f, 0.0f, 1.0f);
        if (orthographic) {
            pinholeScene.cameras[0].type = CameraType::Orthographic;
            pinholeScene.cameras[0].imagePlaneWidth = 3.0f;
        }
        const BothImages pinhole = renderBoth(pinholeScene, options);
        ASSERT_GT(distance(pinhole.cpu, Image(32, 32)).maxSteps, 100) << "the sphere is in view";
        for (const float D : {1e19f, 1e20f, 1e30f, 3e38f}) {
            SCOPED_TRACE(std::string(orthographic ? "orthographic" : "perspective") + ", focus distance " + std::to_string(D));
            Scene far = pinholeScene;
            far.cameras[0].focusDistance = D;
            far.cameras[0].aperture = 1e-3f;
            const BothImages lens = renderBoth(far, options);
            EXPECT_TRUE(agrees(distance(lens.cpu, pinhole.cpu))) << distance(lens.cpu, pinhole.cpu).describe();
            EXPECT_TRUE(agrees(distance(lens.gpu, pinhole.gpu))) << distance(lens.gpu, pinhole.gpu).describe();
        }
    }
}

TEST(DepthOfField, APointOffTheFocusPlaneBlursIntoTheCircleOfConfusion) {
    // 64 px over an image plane 0.5 wide at focal length 1: a pixel at distance z spans z / 128.
    // Circle of confusion A |d - D| / d at the focus plane, in pixels: A |d - D| / d * 128 / D.
    const float A = 0.75f;
    struct Case {
        float d, D, radius;
    };
    for (const Case k : {Case{4.0f, 2.0f, 0.09f}, Case{2.0f, 4.0f, 0.045f}}) {  // behind and before the focus plane
        SCOPED_TRACE("d=" + std::to_string(k.d) + " D=" + std::to_string(k.D));
        const double expected = A * std::fabs(k.d - k.D) / k.d * 128.0 / k.D;  // 24 px for both
        const BothImages images = renderBoth(sphereOffFocus(k.d, k.D, A, k.radius), smallOptions(64, 64, 256));
        const double cpu = discDiameter(images.cpu, expected), gpu = discDiameter(images.gpu, expected);
        recordNote("circle of confusion d=" + std::to_string(k.d).substr(0, 3) + " D=" + std::to_string(k.D).substr(0, 3),
                   "expected " + std::to_string(expected) + " px, CPU " + std::to_string(cpu) + " px, GPU " + std::to_string(gpu) + " px");
        EXPECT_NEAR(cpu, expected, 0.05 * expected);
        EXPECT_NEAR(gpu, expected, 0.05 * expected);
        // The pinhole image of the same sphere is a few pixels wide: the disc is the lens's doing.
        const BothImages sharp = renderBoth(sphereOffFocus(k.d, k.D, 0.0f, k.radius), smallOptions(64, 64, 16));
        std::size_t lit = 0;
        for (const glm::vec3& p : sharp.cpu.pixels) lit += p.g > 0.0f;
        EXPECT_LT(lit, 50u);
    }
}

TEST(DepthOfField, TheGeneralKernelRendersAPinholeBitForBit) {
    expectGeneralKernelRendersItBitForBit(tiledWall(3.0f, 0.0f), smallOptions(32, 32, 4), "thin-lens");
}

TEST(DepthOfField, BothDevicesAgreeOnADefocusedScene) {
    Scene scene = tiledWall(3.0f, 0.5f);
    scene.cameras[0].focusDistance = 2.0f;  // the wall is out of focus
    scene.shapes.push_back(sphere({0.3f, -0.2f, -2.0f}, 0.2f, add(scene, blinnPhong({0.8f, 0.2f, 0.2f}, glm::vec3(0.5f), 32.0f))));
    const BothImages images = renderBoth(scene, smallOptions(64, 64, 16));
    const Distance d = distance(images.gpu, images.cpu);
    recordRow("depth of field: defocused tiles and a sharp sphere", d);
    EXPECT_TRUE(agrees(d)) << d.describe();
    EXPECT_NE(images.gpuStats.features.find("thin-lens"), std::string::npos) << images.gpuStats.features;
}

}  // namespace
}  // namespace vkrt::stability
