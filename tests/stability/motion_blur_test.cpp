// Motion blur (issue 21): instances with a second pose (<transformEnd> / xformEnd), a time per
// camera sample in the shutter (RENDERING.md §9), on both devices:
//   - a box edge moving m pixels during the shutter, seen orthographically, is the closed-form ramp
//     of width m, per pixel;
//   - an end pose equal to the start renders bit for bit as a static instance; a shutter of zero
//     length at 0 (at 1) renders the start (end) pose; a scene without motion ignores --shutter;
//   - a bar turning from -40 to +40 degrees blurs symmetrically about its mid-shutter pose, and the
//   mid-shutter time renders that pose;
//   - the top level's box of a moving instance holds it at every time (motionBounds);
//   - the two devices agree by the project's rule.
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "both_paths.h"
#include "gpu_environment.h"
#include "instance_motion.h"
#include "motion.h"
#include "scene_building.h"

namespace vkrt::stability {
namespace {

glm::mat4 translation(glm::vec3 t) { return glm::translate(glm::mat4(1.0f), t); }
glm::mat4 rotationZ(float degrees) { return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 0, 1)); }

// A white box prototype lit head-on (a point light far along +z: N.L = 1 - 2e-8), black behind,
// seen orthographically along -z through a plane `planeWidth` wide; the box placed by `start`
// and, when `end` is given, moving to it.
Scene litBox(glm::vec3 lo, glm::vec3 hi, float planeWidth, const glm::mat4& start, const glm::mat4* end) {
    Scene scene;
    scene.path = "a moving white box (built in code)";
    scene.background = glm::vec3(0.0f);
    scene.cameras.push_back(orthographic({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, planeWidth));
    scene.lights.push_back(pointLight({0.0f, 0.0f, 1e4f}, glm::vec3(1.0f)));
    scene.prototypes.push_back(box(lo, hi, add(scene, lambertian(glm::vec3(1.0f)))));
    Instance instance;
    instance.prototype = 0;
    instance.objectToWorld = start;
    if (end) {
        instance.moving = true;
        instance.objectToWorldEnd = *end;
    }
    scene.instances.push_back(instance);
    return scene;
}

// The edge x = -1 moves to x = 0 over the shutter: 16 pixels of a 64-pixel plane 4 units wide.
Scene slidingEdge(bool moving) {
    const glm::mat4 start = translation({-1.0f, 0.0f, 0.0f}), end = translation({0.0f, 0.0f, 0.0f});
    return litBox({-10.0f, -10.0f, -1.0f}, {0.0f, 10.0f, 0.0f}, 4.0f, start, moving ? &end : nullptr);
}

// Pixel i's expected value: the box covers x < -1 + t for shutter time t in [0, 1], so a point x
// is covered a fraction clamp(-x, 0, 1) of the shutter; the pixel averages that over its width
// (midpoint rule on 4096 points: exact to 1e-7 for this piecewise-linear function).
double rampPixel(int i, int width, double planeWidth) {
    const double a = planeWidth * (static_cast<double>(i) / width - 0.5), p = planeWidth / width;
    double sum = 0.0;
    for (int k = 0; k < 4096; ++k) sum += std::clamp(-(a + p * (k + 0.5) / 4096.0), 0.0, 1.0);
    return sum / 4096.0;
}

TEST(MotionBlur, AMovingEdgeIsTheClosedFormRampOfItsWidthInPixels) {
    const RenderOptions options = smallOptions(64, 4, 4096);
    const BothImages b = renderBoth(slidingEdge(true), options);
    EXPECT_NE(b.gpuStats.features.find("motion"), std::string::npos) << b.gpuStats.features;
    // 4096 samples, the pixel (x) and time strata each stratified and paired at random: a pixel's
    // coverage is a mean of 0/1 values with standard deviation <= 0.5 / 64 = 0.0078; 0.04 is 5 sigma.
    constexpr double kTolerance = 0.04;
    for (const Image* image : {&b.cpu, &b.gpu}) {
        Deviation dev;
        int ramp = 0;
        for (int j = 0; j < options.height; ++j)
            for (int i = 0; i < options.width; ++i) {
                const double expected = rampPixel(i, options.width, 4.0);
                const double got = image->at(i, j).g;
                dev.add(std::abs(got - expected), std::abs(got - expected) <= kTolerance,
                        "pixel " + std::to_string(i) + "," + std::to_string(j) + ": " + std::to_string(got) + " vs " +
                            std::to_string(expected));
                if (j == 0) ramp += got > 0.02 && got < 0.98;
            }
        EXPECT_EQ(dev.wrong, 0) << (image == &b.cpu ? "CPU " : "GPU ") << dev.first << " (worst " << dev.worst << ")";
        // The edge moved 16 pixels: exactly the 16 pixels it swept are partly covered.
        EXPECT_EQ(ramp, 16) << (image == &b.cpu ? "CPU" : "GPU");
        recordNote(std::string("motion ramp (16 px, 4096 rpp), ") + (image == &b.cpu ? "CPU" : "GPU"),
                   "worst |pixel - closed form| " + std::to_string(dev.worst) + ", ramp " + std::to_string(ramp) + " px");
    }
    const Distance d = distance(b.gpu, b.cpu);
    recordRow("motion blur ramp: GPU vs CPU", d);
    EXPECT_TRUE(agrees(d)) << d.describe();
}

TEST(MotionBlur, AnEndPoseEqualToTheStartIsAStaticInstanceBitForBit) {
    const glm::mat4 pose = translation({-0.5f, 0.0f, 0.0f}) * rotationZ(20.0f);
    const Scene still = litBox({-1.0f, -0.5f, -1.0f}, {1.0f, 0.5f, 0.0f}, 4.0f, pose, nullptr);
    const Scene same = litBox({-1.0f, -0.5f, -1.0f}, {1.0f, 0.5f, 0.0f}, 4.0f, pose, &pose);
    const RenderOptions options = smallOptions(32, 32, 4);
    const BothImages a = renderBoth(still, options), b = renderBoth(same, options);
    EXPECT_EQ(b.gpuStats.features.find("motion"), std::string::npos) << b.gpuStats.features;
    for (std::size_t i = 0; i < a.cpu.pixels.size(); ++i) {
        ASSERT_EQ(a.cpu.pixels[i], b.cpu.pixels[i]) << "CPU pixel " << i;
        ASSERT_EQ(a.gpu.pixels[i], b.gpu.pixels[i]) << "GPU pixel " << i;
    }
}

TEST(MotionBlur, AShutterOfZeroLengthRendersThatPose) {
    const glm::mat4 start = translation({-0.5f, 0.2f, 0.0f}) * rotationZ(-30.0f);
    const glm::mat4 end = translation({0.7f, -0.1f, 0.0f}) * rotationZ(50.0f) * glm::scale(glm::mat4(1.0f), glm::vec3(1.3f, 0.8f, 1.0f));
    const glm::vec3 lo(-1.0f, -0.5f, -1.0f), hi(1.0f, 0.5f, 0.0f);
    const Scene moving = litBox(lo, hi, 4.0f, start, &end);
    RenderOptions options = smallOptions(48, 48, 4);
    for (const float t : {0.0f, 1.0f}) {
        options.shutter = glm::vec2(t, t);
        const BothImages posed = renderBoth(moving, options);
        const BothImages still = renderBoth(litBox(lo, hi, 4.0f, t == 0.0f ? start : end, nullptr), options);
        // The pose recomposed from its decomposition (T * R * S in float) differs from the
        // composed matrix by a few ulps: at most a silhouette pixel may tip, which the agreement
        // rule allows.
        const Distance cpu = distance(posed.cpu, still.cpu), gpu = distance(posed.gpu, still.gpu);
        EXPECT_TRUE(agrees(cpu)) << "time " << t << " CPU " << cpu.describe();
        EXPECT_TRUE(agrees(gpu)) << "time " << t << " GPU " << gpu.describe();
        recordRow(std::string("motion: shutter ") + (t == 0.0f ? "0,0 vs the start pose" : "1,1 vs the end pose"), cpu, gpu,
                  distance(posed.gpu, posed.cpu));
    }
    // A mirrored instance (negative determinant in both poses) moves the same way.
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
    const glm::mat4 mirroredStart = start * mirror, mirroredEnd = end * mirror;
    options.shutter = glm::vec2(1.0f, 1.0f);
    const BothImages posed = renderBoth(litBox(lo, hi, 4.0f, mirroredStart, &mirroredEnd), options);
    const BothImages still = renderBoth(litBox(lo, hi, 4.0f, mirroredEnd, nullptr), options);
    EXPECT_TRUE(agrees(distance(posed.cpu, still.cpu))) << distance(posed.cpu, still.cpu).describe();
    EXPECT_TRUE(agrees(distance(posed.gpu, still.gpu))) << distance(posed.gpu, still.gpu).describe();
}

TEST(MotionBlur, ASceneWithoutMotionIgnoresTheShutter) {
    const Scene still = slidingEdge(false);
    RenderOptions options = smallOptions(32, 8, 16);
    const BothImages a = renderBoth(still, options);
    options.shutter = glm::vec2(0.25f, 0.75f);
    const BothImages b = renderBoth(still, options);
    EXPECT_EQ(b.gpuStats.features.find("motion"), std::string::npos) << b.gpuStats.features;
    for (std::size_t i = 0; i < a.cpu.pixels.size(); ++i) {
        ASSERT_EQ(a.cpu.pixels[i], b.cpu.pixels[i]) << "CPU pixel " << i;
        ASSERT_EQ(a.gpu.pixels[i], b.gpu.pixels[i]) << "GPU pixel " << i;
    }
}

// A bar along x turning about z from `from` to `to` degrees.
Scene turningBar(float from, float to) {
    const glm::mat4 start = rotationZ(from), end = rotationZ(to);
    return litBox({-1.5f, -0.2f, -1.0f}, {1.5f, 0.2f, 0.0f}, 4.0f, start, &end);
}

// Largest and mean |pixel - its mirror image across the row axis y = 0|.
std::pair<double, double> flipDifference(const Image& image) {
    double worst = 0.0, sum = 0.0;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const double d = std::abs(image.at(i, j).g - image.at(i, image.height - 1 - j).g);
            worst = std::max(worst, d);
            sum += d;
        }
    return {worst, sum / (image.width * image.height)};
}

TEST(MotionBlur, ATurningBarBlursSymmetricallyAboutItsMidShutterPose) {
    const RenderOptions options = smallOptions(48, 48, 2048);
    const BothImages symmetric = renderBoth(turningBar(-40.0f, 40.0f), options);
    const BothImages lopsided = renderBoth(turningBar(-40.0f, 10.0f), options);
    // Mirroring y maps the pose at angle a to the pose at -a, so the blur of [-40, 40] is its own
    // mirror image. Each pixel is a mean of 2048 0/1 coverages (sd <= 0.011); a pixel and its
    // mirror differ by sd <= 0.016, and 0.08 is 5 of those. The lopsided motion breaks the
    // symmetry by far more (the bar's tip sweeps 30 degrees on one side only).
    for (const Image* image : {&symmetric.cpu, &symmetric.gpu}) {
        const auto [worst, mean] = flipDifference(*image);
        EXPECT_LT(worst, 0.08) << (image == &symmetric.cpu ? "CPU" : "GPU");
        EXPECT_LT(mean, 0.005) << (image == &symmetric.cpu ? "CPU" : "GPU");
        recordNote(std::string("motion: turning bar vs its mirror image, ") + (image == &symmetric.cpu ? "CPU" : "GPU"),
                   "worst " + std::to_string(worst) + ", mean " + std::to_string(mean));
    }
    for (const Image* image : {&lopsided.cpu, &lopsided.gpu}) EXPECT_GT(flipDifference(*image).first, 0.3);
    const Distance d = distance(symmetric.gpu, symmetric.cpu);
    recordRow("motion blur turning bar: GPU vs CPU", d);
    EXPECT_TRUE(agrees(d)) << d.describe();

    // Slerp's midpoint is the mid pose: at time 0.5 the bar lies along x.
    RenderOptions mid = smallOptions(48, 48, 4);
    mid.shutter = glm::vec2(0.5f, 0.5f);
    const BothImages half = renderBoth(turningBar(-40.0f, 40.0f), mid);
    const BothImages flat = renderBoth(litBox({-1.5f, -0.2f, -1.0f}, {1.5f, 0.2f, 0.0f}, 4.0f, glm::mat4(1.0f), nullptr), mid);
    EXPECT_TRUE(agrees(distance(half.cpu, flat.cpu))) << distance(half.cpu, flat.cpu).describe();
    EXPECT_TRUE(agrees(distance(half.gpu, flat.gpu))) << distance(half.gpu, flat.gpu).describe();
}

// The top level's box of a moving instance holds every pose (bvh_builder/instance_motion.h): 2000
// random times of random motions (translation, rotation up to a half turn, stretch), each pose's
// transformed box corners inside the bounds.
TEST(MotionBlur, TheBoundsOfAMovingInstanceHoldItAtEveryTime) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const bvh::Aabb object{glm::vec3(-1.0f, -0.5f, -2.0f), glm::vec3(1.5f, 0.5f, 0.25f)};
    int outside = 0;
    for (int trial = 0; trial < 50; ++trial) {
        const auto pose = [&] {
            const glm::vec3 axis = glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + glm::vec3(0.0f, 0.0f, 1e-3f));
            return glm::translate(glm::mat4(1.0f), 3.0f * glm::vec3(unit(rng), unit(rng), unit(rng))) *
                   glm::rotate(glm::mat4(1.0f), 3.1f * unit(rng), axis) *
                   glm::scale(glm::mat4(1.0f), glm::vec3(1.2f + unit(rng), 1.2f + unit(rng), 1.2f + unit(rng)));
        };
        const glm::mat4 start = pose(), end = pose();
        const gpu::InstanceMotion m = bvh::decomposeMotion(start, end);
        const bvh::Aabb bounds = bvh::motionBounds(object, m);
        for (int k = 0; k < 40; ++k) {
            const float t = 0.5f + 0.5f * unit(rng);
            const gpu::Instance posed = motion::instanceAtTime(gpu::Instance{}, m, t);
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 p((corner & 1) ? object.hi.x : object.lo.x, (corner & 2) ? object.hi.y : object.lo.y,
                                  (corner & 4) ? object.hi.z : object.lo.z);
                for (int r = 0; r < 3; ++r) {
                    const float w = glm::dot(glm::vec3(posed.objectToWorld[r]), p) + posed.objectToWorld[r].w;
                    outside += w < bounds.lo[r] || w > bounds.hi[r];
                }
            }
        }
        // The decomposition reproduces both poses (to float rounding of the recomposition).
        for (const float t : {0.0f, 1.0f}) {
            const gpu::Instance posed = motion::instanceAtTime(gpu::Instance{}, m, t);
            const glm::mat4& given = t == 0.0f ? start : end;
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 4; ++c) EXPECT_NEAR(posed.objectToWorld[r][c], given[c][r], 2e-5f) << trial << " t " << t;
        }
    }
    EXPECT_EQ(outside, 0);
}

TEST(MotionBlur, OppositeHandednessCannotBeDecomposed) {
    const glm::mat4 start(1.0f), end = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));
    EXPECT_TRUE(bvh::motionProblem(start, end).has_value());
    EXPECT_THROW(bvh::decomposeMotion(start, end), std::invalid_argument);
    EXPECT_FALSE(bvh::motionProblem(end, end * rotationZ(30.0f)).has_value());
}

}  // namespace
}  // namespace vkrt::stability
