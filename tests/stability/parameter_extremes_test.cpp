// Parameters at their ends (issue 7), on both paths: roughness 0 and huge, an area light of size 0,
// phongExp 0 and 1e6, refractive index 1 and total internal reflection, 1 and 4096 samples, images
// of 1x1 and 16384x16, max depth 0 and 64, light intensities 0 and 1e6. Each is compared with an
// exact identity or a closed form, not just with the other path.
#include <cmath>
#include <cstdio>
#include <sstream>
#include <tuple>

#include <gtest/gtest.h>

#include "both_paths.h"
#include "invariance_scene.h"
#include "region_checks.h"
#include "scene_building.h"
#include "scene_rules.h"

namespace vkrt::stability {
namespace {

const glm::vec3 kSky(0.0f, 0.0f, 1.0f);

// A mirror ball and a mirror floor tile among coloured objects (what a mirror shows varies a lot).
Scene mirrorScene(const Shader& mirrorShader) {
    Scene scene;
    scene.path = "mirrors (built in code)";
    scene.background = glm::vec3(0.1f, 0.1f, 0.3f);
    scene.cameras.push_back(perspective({0.0f, 1.5f, 5.0f}, {0.0f, 0.5f, 0.0f}, 1.0f, 1.0f));
    scene.lights.push_back(pointLight({2.0f, 5.0f, 3.0f}, glm::vec3(0.9f)));
    const int m = add(scene, mirrorShader);
    const int grey = add(scene, lambertian(glm::vec3(0.6f)));
    const int red = add(scene, blinnPhong({0.8f, 0.1f, 0.1f}, glm::vec3(0.4f), 32.0f));
    const int green = add(scene, lambertian({0.1f, 0.7f, 0.2f}));
    scene.shapes.push_back(box({-4.0f, -0.5f, -4.0f}, {4.0f, 0.0f, 4.0f}, grey));
    scene.shapes.push_back(box({-1.5f, 0.0f, -1.0f}, {1.5f, 0.01f, 1.5f}, m));
    scene.shapes.push_back(sphere({0.0f, 0.8f, 0.0f}, 0.8f, m));
    scene.shapes.push_back(sphere({-1.6f, 0.5f, -1.2f}, 0.5f, red));
    scene.shapes.push_back(box({1.0f, 0.0f, -1.8f}, {2.0f, 1.2f, -0.8f}, green));
    return scene;
}

TEST(Roughness, ZeroIsExactlyTheMirror) {
    // A BlinnPhongMirrored or Glaze shader with no local colour and mirrorCoef 1 is (1 - 1) * local
    // + 1 * R = R: bit for bit the Mirror's image when roughness 0 takes the mirror direction.
    const BothImages reference = renderBoth(mirrorScene(mirror(0.0f)), smallOptions(48, 48, 4));
    Shader mirrored = glossy(glm::vec3(0.0f), 1.0f, 0.0f);
    mirrored.specular = glm::vec3(0.0f);
    Shader glaze = mirrored;
    glaze.type = ShaderType::Glaze;
    for (const auto& [name, shader] : {std::pair{"BlinnPhongMirrored m=1 roughness 0", mirrored}, std::pair{"Glaze m=1 roughness 0", glaze}}) {
        const BothImages im = renderBoth(mirrorScene(shader), smallOptions(48, 48, 4));
        const Distance cpu = distance(im.cpu, reference.cpu), gpu = distance(im.gpu, reference.gpu);
        recordRow(std::string(name) + " vs Mirror", cpu, gpu, distance(im.gpu, im.cpu));
        EXPECT_EQ(cpu.maxSteps, 0) << name << ": " << cpu.describe();
        EXPECT_EQ(gpu.maxSteps, 0) << name << ": " << gpu.describe();
    }
}

TEST(Roughness, ApproachesTheMirrorContinuously) {
    // Roughness 1e-7 perturbs directions by < 1e-7 rad: the glossy code path (4 gloss samples)
    // must give the mirror's image up to rays that graze an edge (the invariance tolerance).
    RenderOptions options = smallOptions(48, 48, 4);
    const BothImages mirrorImages = renderBoth(mirrorScene(mirror(0.0f)), options);
    options.glossSamples = 4;
    const BothImages im = renderBoth(mirrorScene(mirror(1e-7f)), options);
    const Distance cpu = distance(im.cpu, mirrorImages.cpu), gpu = distance(im.gpu, mirrorImages.gpu);
    recordRow("roughness 1e-7 vs roughness 0", cpu, gpu, distance(im.gpu, im.cpu));
    EXPECT_TRUE(agrees(cpu)) << cpu.describe();
    EXPECT_TRUE(agrees(gpu)) << gpu.describe();
    EXPECT_EQ(compareSmoothRegions(mirrorImages.cpu, im.cpu, 3, 2).differing, 0);
    EXPECT_EQ(compareSmoothRegions(mirrorImages.gpu, im.gpu, 3, 2).differing, 0);
}

class HugeRoughness : public ::testing::TestWithParam<float> {};

TEST_P(HugeRoughness, DirectionsBelowTheSurfaceAreBlack) {
    // A thin mirror tile (two triangles) with a red ball under it and only sky above. Huge roughness
    // spreads the directions over the plane perpendicular to the mirror direction, so about half
    // point below the tile: those are black (RENDERING.md §5), never the red ball, never NaN (at
    // 1e30 the perturbed vector's squared length overflows float).
    const float roughness = GetParam();
    Scene scene;
    scene.path = "huge roughness (built in code)";
    scene.background = kSky;
    scene.cameras.push_back(perspective({0.0f, 2.0f, 3.0f}, {0.0f, 0.0f, 0.0f}, 1.0f, 0.6f));
    scene.lights.push_back(pointLight({0.0f, -3.0f, 0.0f}, glm::vec3(1.0f)));  // lights the ball from below
    const int m = add(scene, mirror(roughness));
    const int red = add(scene, lambertian({1.0f, 0.0f, 0.0f}));
    scene.shapes.push_back(triangle({-5.0f, 0.0f, -5.0f}, {-5.0f, 0.0f, 5.0f}, {5.0f, 0.0f, 5.0f}, m));
    scene.shapes.push_back(triangle({-5.0f, 0.0f, -5.0f}, {5.0f, 0.0f, 5.0f}, {5.0f, 0.0f, -5.0f}, m));
    scene.shapes.push_back(sphere({0.0f, -1.5f, 0.0f}, 1.0f, red));
    RenderOptions options = smallOptions(32, 32, 4);
    options.glossSamples = 4;
    const BothImages im = renderBoth(scene, options);
    Deviation dev[2];  // red/green: light from below the mirror
    for (const auto& [k, image] : {std::pair{0, &im.cpu}, std::pair{1, &im.gpu}}) {
        double blue = 0.0;
        for (const glm::vec3& c : image->pixels) {
            const double below = std::max(c.x, c.y);
            dev[k].add(below, below == 0.0, std::to_string(c.x) + " " + std::to_string(c.y));
            blue += c.z;
        }
        blue /= static_cast<double>(image->pixels.size());
        EXPECT_EQ(dev[k].wrong, 0) << (k ? "GPU" : "CPU") << ": light from below the mirror, " << dev[k].first;
        // Some directions see the sky, some are black: the mean is strictly between.
        EXPECT_GT(blue, 0.2) << (k ? "GPU" : "CPU");
        EXPECT_LT(blue, 0.8) << (k ? "GPU" : "CPU");
    }
    std::ostringstream name;
    name << "roughness " << roughness << " (red/green from below the mirror vs 0)";
    const Distance d = distance(im.gpu, im.cpu);
    recordRow(name.str(), dev[0].asDistance(), dev[1].asDistance(), d);
    EXPECT_TRUE(agrees(d)) << d.describe();
}

INSTANTIATE_TEST_SUITE_P(Values, HugeRoughness, ::testing::Values(10.0f, 1e4f, 1e30f),
                         [](const auto& info) { return "Roughness" + std::to_string(info.index); });

// viewDir 0 0 -1e-25 names the same direction as 0 0 -1, and focalLength 1e20 over imagePlaneWidth
// 5e19 the same field as 2 over 1. With the loader's conditioning (rules::conditionCamera) the
// extreme directions render bit-identically to the plain camera on both devices (an axis gaze
// normalises to exactly (0,0,-1) at any length). The focal pair keeps its ratio exactly but lands
// on 2m and m with m = 1.0842 (5e19's mantissa), not 2 and 1, so the ray directions round
// differently by an ulp: no pixel may move by an 8-bit step. Without the conditioning |v|^2
// underflows or overflows in float and every pixel was background.
TEST(CameraExtremes, TinyViewDirAndHugeFocalLengthRenderTheSameImage) {
    Scene plain = mirrorScene(mirror());
    plain.cameras[0] = perspective({0.0f, 1.5f, 5.0f}, {0.0f, 1.5f, 4.0f}, 2.0f, 1.0f);
    const BothImages reference = renderBoth(plain, smallOptions(48, 32, 1));
    for (const auto& [gazeScale, focalScale] : {std::pair{1e-25f, 1.0f}, std::pair{1e20f, 1.0f}, std::pair{1.0f, 5e19f}}) {
        SCOPED_TRACE(::testing::Message() << "gaze x" << gazeScale << ", focal and width x" << focalScale);
        Scene extreme = plain;
        extreme.cameras[0].gaze *= gazeScale;
        extreme.cameras[0].focalLength *= focalScale;
        extreme.cameras[0].imagePlaneWidth *= focalScale;
        rules::conditionCamera(extreme.cameras[0]);
        const BothImages got = renderBoth(extreme, smallOptions(48, 32, 1));
        EXPECT_EQ(distance(got.cpu, reference.cpu).maxSteps, 0);
        EXPECT_EQ(distance(got.gpu, reference.gpu).maxSteps, 0);
        if (focalScale == 1.0f) {
            EXPECT_TRUE(got.cpu.pixels == reference.cpu.pixels);
            EXPECT_TRUE(got.gpu.pixels == reference.gpu.pixels);
        }
    }
}

TEST(AreaLight, OfSizeZeroIsExactlyThePointLight) {
    // RENDERING.md §4: a sample point is c + (su - 0.5) * 0 * T + ... = c, and each sample carries
    // the full intensity. (The XML loader refuses width/length 0 as a likely mistake, so this scene
    // is built in code.)
    Scene point = invarianceScene();
    point.lights = {pointLight({0.8f, 7.0f, 2.0f}, glm::vec3(0.9f))};
    Scene area = point;
    area.lights = {areaLight({0.8f, 7.0f, 2.0f}, {0.0f, -1.0f, 0.0f}, 0.0f, 0.0f, glm::vec3(0.9f))};
    for (int lightSamples : {1, 4}) {
        RenderOptions options = smallOptions(48, 48, 4);
        options.lightSamples = lightSamples;
        const BothImages p = renderBoth(point, options), a = renderBoth(area, options);
        const Distance cpu = distance(a.cpu, p.cpu), gpu = distance(a.gpu, p.gpu);
        recordRow("area light 0x0 vs point light, " + std::to_string(lightSamples) + " light samples", cpu, gpu,
                  distance(a.gpu, a.cpu));
        // One sample: the same float operations, bit for bit. Four: the mean (x + x + x + x) / 4 may
        // round in its last bit, which can move one 8-bit step.
        const int allowed = lightSamples == 1 ? 0 : 1;
        EXPECT_LE(cpu.maxSteps, allowed) << cpu.describe();
        EXPECT_LE(gpu.maxSteps, allowed) << gpu.describe();
    }
}

// ---- Blinn-Phong exponent ---------------------------------------------------------------------

// A flat floor under a light 1e4 above (N.L within 3e-5 of 1), seen from above at an angle.
Scene flatFloor(const Shader& shader) {
    Scene scene;
    scene.path = "flat floor (built in code)";
    scene.background = kSky;
    scene.cameras.push_back(perspective({0.0f, 3.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 1.0f, 1.0f));
    scene.lights.push_back(pointLight({0.0f, 1e4f, 0.0f}, glm::vec3(1.0f)));
    add(scene, shader);
    scene.shapes.push_back(box({-20.0f, -1.0f, -20.0f}, {20.0f, 0.0f, 20.0f}, 0));
    return scene;
}

// Every pixel against one colour, within 1e-3 (N.L is 1 within 3e-5 here).
Deviation againstConstant(const Image& image, glm::vec3 expected) {
    Deviation d;
    for (const glm::vec3& c : image.pixels) {
        const glm::vec3 e = glm::abs(c - expected);
        const double error = std::max(e.x, std::max(e.y, e.z));
        d.add(error, error <= 1e-3, std::to_string(c.x) + " " + std::to_string(c.y) + " " + std::to_string(c.z));
    }
    return d;
}

TEST(PhongExponent, ZeroGivesAHighlightOfOneEverywhere) {
    // max(0, N.H)^0 = 1 by definition (RENDERING.md §5): every floor pixel is (kd + ks) * I * 1.
    const BothImages im = renderBoth(flatFloor(blinnPhong({0.3f, 0.0f, 0.0f}, glm::vec3(0.2f), 0.0f)), smallOptions(32, 32, 4));
    const Deviation cpu = againstConstant(im.cpu, {0.5f, 0.2f, 0.2f}), gpu = againstConstant(im.gpu, {0.5f, 0.2f, 0.2f});
    EXPECT_EQ(cpu.wrong, 0) << "CPU: " << cpu.first;
    EXPECT_EQ(gpu.wrong, 0) << "GPU: " << gpu.first;
    recordRow("phongExp 0 (vs (kd + ks) I)", cpu.asDistance(), gpu.asDistance(), distance(im.gpu, im.cpu));
}

TEST(PhongExponent, HugeGivesAPointHighlight) {
    // (N.H)^1e6 is 1 only where N.H = 1 and below 1e-4 once N.H < 1 - 1e-5: the floor is kd * I
    // except at the single pixel whose ray reflects straight at the light (none here, where the
    // camera looks obliquely), and pow must not produce NaN/Inf.
    const BothImages im = renderBoth(flatFloor(blinnPhong({0.3f, 0.0f, 0.0f}, glm::vec3(0.2f), 1e6f)), smallOptions(32, 32, 4));
    const Deviation cpu = againstConstant(im.cpu, {0.3f, 0.0f, 0.0f}), gpu = againstConstant(im.gpu, {0.3f, 0.0f, 0.0f});
    EXPECT_EQ(cpu.wrong, 0) << "CPU: " << cpu.first;
    EXPECT_EQ(gpu.wrong, 0) << "GPU: " << gpu.first;
    recordRow("phongExp 1e6 (vs kd I)", cpu.asDistance(), gpu.asDistance(), distance(im.gpu, im.cpu));
}

// ---- dielectrics ------------------------------------------------------------------------------

TEST(RefractiveIndex, OneMakesTheObjectInvisible) {
    // F = 0 and an undeviated ray at eta = 1 (RENDERING.md §6): with the glass sphere in front of a
    // patterned wall the image equals the one without it. The light hangs between the sphere and
    // the wall, so the sphere (which blocks shadow rays like any surface) casts no visible shadow.
    auto build = [](bool withSphere) {
        Scene scene;
        scene.path = "invisible glass (built in code)";
        scene.background = kSky;
        scene.cameras.push_back(perspective({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}, 1.0f, 1.0f));
        scene.lights.push_back(pointLight({0.0f, 0.5f, -3.0f}, glm::vec3(1.0f)));
        const int wall = add(scene, lambertian(glm::vec3(0.7f)));
        const int red = add(scene, lambertian({0.9f, 0.1f, 0.1f}));
        const int green = add(scene, lambertian({0.1f, 0.8f, 0.2f}));
        const int glass = add(scene, dielectric(1.0f));
        scene.shapes.push_back(box({-6.0f, -6.0f, -6.0f}, {6.0f, 6.0f, -5.0f}, wall));
        for (int i = -3; i <= 3; ++i)
            for (int j = -3; j <= 3; ++j)
                if ((i + j) % 2 == 0)
                    scene.shapes.push_back(box({0.5f * i - 0.2f, 0.5f * j - 0.2f, -5.0f}, {0.5f * i + 0.2f, 0.5f * j + 0.2f, -4.9f},
                                               (i + 3) % 2 == 0 ? red : green));
        if (withSphere) scene.shapes.push_back(sphere({0.0f, 0.0f, 0.0f}, 1.2f, glass));
        return scene;
    };
    const BothImages with = renderBoth(build(true), smallOptions(48, 48, 4));
    const BothImages without = renderBoth(build(false), smallOptions(48, 48, 4));
    const Distance cpu = distance(with.cpu, without.cpu), gpu = distance(with.gpu, without.gpu);
    recordRow("refractive index 1 (with vs without the sphere)", cpu, gpu, distance(with.gpu, with.cpu));
    // The ray restarts at each boundary from the offset hit point, so it may shift by ULPs: edges of
    // the pattern may flip; smooth regions may not.
    EXPECT_TRUE(agrees(cpu)) << cpu.describe();
    EXPECT_TRUE(agrees(gpu)) << gpu.describe();
    EXPECT_EQ(compareSmoothRegions(without.cpu, with.cpu, 3, 2).differing, 0);
    EXPECT_EQ(compareSmoothRegions(without.gpu, with.gpu, 3, 2).differing, 0);
}

TEST(TotalInternalReflection, KeepsTheOutsideUnreachableBeyondTheCriticalAngle) {
    // The camera inside a large glass slab (eta 1.5, critical angle 41.8 degrees) looks up at its top
    // face at angle theta; above it, a green ceiling lit from below, the only non-black thing. At 30
    // degrees the ceiling is seen through the face; at 50 degrees F = 1, and every reflection keeps the
    // same angle to the horizontal faces, so the ceiling can never be reached: exactly black.
    for (double theta : {30.0, 50.0}) {
        Scene scene;
        scene.path = "total internal reflection (built in code)";
        scene.background = glm::vec3(0.0f);
        const double rad = theta * 3.14159265358979 / 180.0;
        const glm::vec3 gaze(glm::dvec3(std::sin(rad), std::cos(rad), 0.0));
        scene.cameras.push_back(orthographic({0.0f, -50.0f, 0.0f}, gaze, 1.0f));
        scene.lights.push_back(pointLight({0.0f, 5.0f, 0.0f}, glm::vec3(1.0f)));
        const int glass = add(scene, dielectric(1.5f));
        const int green = add(scene, lambertian({0.0f, 0.8f, 0.0f}));
        // Wide enough that 16 bounces (about 120 sideways each) never reach a side face, out of which a
        // ray could leave sideways and climb to the ceiling.
        scene.shapes.push_back(box({-1e5f, -100.0f, -1e5f}, {1e5f, 0.0f, 1e5f}, glass));
        scene.shapes.push_back(box({-1e6f, 10.0f, -1e6f}, {1e6f, 11.0f, 1e6f}, green));
        RenderOptions options = smallOptions(16, 16, 1);
        options.maxDepth = 16;
        const BothImages im = renderBoth(scene, options);
        Deviation dev[2];  // beyond the critical angle: any light at all; below it: the shortfall under 0.02
        for (const auto& [k, image] : {std::pair{0, &im.cpu}, std::pair{1, &im.gpu}})
            for (const glm::vec3& c : image->pixels) {
                const double error = theta < 41.8 ? std::max(0.0, 0.02 - c.y) : std::max(c.x, std::max(c.y, c.z));
                dev[k].add(error, error == 0.0, std::to_string(c.y));
            }
        const char* what = theta < 41.8 ? "the ceiling must show through below the critical angle"
                                        : "light refracted beyond the critical angle";
        EXPECT_EQ(dev[0].wrong, 0) << "CPU: " << what << ", " << dev[0].first;
        EXPECT_EQ(dev[1].wrong, 0) << "GPU: " << what << ", " << dev[1].first;
        std::ostringstream name;
        name << "glass slab at " << theta << " degrees" << (theta > 41.8 ? " (total internal reflection: vs black)" : " (ceiling seen)");
        const Distance d = distance(im.gpu, im.cpu);
        recordRow(name.str(), dev[0].asDistance(), dev[1].asDistance(), d);
        EXPECT_TRUE(agrees(d)) << d.describe();
    }
}

// ---- sampling and image size -----------------------------------------------------------------

TEST(Samples, OneAnd4096PerPixel) {
    const Scene scene = invarianceScene();
    const BothImages one = renderBoth(scene, smallOptions(32, 32, 1));
    const Distance d1 = distance(one.gpu, one.cpu);
    recordRow("1 sample per pixel (32x32)", d1);
    EXPECT_TRUE(agrees(d1)) << d1.describe();
    // 4096 samples on 4x4 pixels: each pixel averages a large part of the scene. Against 1024
    // samples the difference is Monte Carlo noise, whose standard deviation here is below 1/255
    // (the area light's penumbrae are the only noise, 64x64 strata): 3/255 bounds it.
    const BothImages many = renderBoth(scene, smallOptions(4, 4, 4096));
    const BothImages fewer = renderBoth(scene, smallOptions(4, 4, 1024));
    const Distance d = distance(many.gpu, many.cpu);
    recordRow("4096 samples per pixel (4x4)", distance(many.cpu, fewer.cpu), distance(many.gpu, fewer.gpu), d);
    EXPECT_TRUE(agrees(d)) << d.describe();
    EXPECT_LE(distance(many.cpu, fewer.cpu).maxSteps, 3);
    EXPECT_LE(distance(many.gpu, fewer.gpu).maxSteps, 3);
}

TEST(ImageSize, OneByOneAnd16384By16) {
    const Scene scene = invarianceScene();
    // The single pixel takes 64 samples spread over the whole view, so it cannot be pure background.
    for (const auto& [w, h, rpp] : {std::tuple{1, 1, 64}, std::tuple{16384, 16, 1}}) {
        const BothImages im = renderBoth(scene, smallOptions(w, h, rpp));
        ASSERT_EQ(im.gpu.width, w);
        ASSERT_EQ(im.gpu.height, h);
        const Distance d = distance(im.gpu, im.cpu);
        recordRow("image " + std::to_string(w) + "x" + std::to_string(h), d);
        EXPECT_TRUE(agrees(d)) << d.describe();
        // The wide strip crosses the whole view: background at both ends, the scene in between.
        int notBackground = 0;
        for (const glm::vec3& c : im.gpu.pixels) notBackground += c != scene.background ? 1 : 0;
        EXPECT_GT(notBackground, 0);
    }
}

// ---- recursion depth --------------------------------------------------------------------------

// Two parallel mirrors facing each other (a hall of mirrors) with a lit ball and a glass ball
// between them: every reflection sees another one, so depth 64 is really used.
Scene hallOfMirrors(const Shader& mirrorShader) {
    Scene scene;
    scene.path = "hall of mirrors (built in code)";
    scene.background = glm::vec3(0.05f, 0.05f, 0.1f);
    scene.cameras.push_back(perspective({0.3f, 0.5f, 1.6f}, {-0.5f, 0.2f, 0.0f}, 1.0f, 1.2f));
    scene.lights.push_back(pointLight({0.0f, 2.0f, 0.0f}, glm::vec3(0.9f)));
    const int m = add(scene, mirrorShader);
    const int red = add(scene, lambertian({0.8f, 0.2f, 0.1f}));
    const int glass = add(scene, dielectric(1.5f, glm::vec3(0.9f)));
    scene.shapes.push_back(box({-2.1f, -1.0f, -3.0f}, {-2.0f, 3.0f, 3.0f}, m));
    scene.shapes.push_back(box({2.0f, -1.0f, -3.0f}, {2.1f, 3.0f, 3.0f}, m));
    scene.shapes.push_back(sphere({0.0f, 0.3f, -0.5f}, 0.4f, red));
    scene.shapes.push_back(sphere({-0.9f, 0.3f, 0.2f}, 0.3f, glass));
    return scene;
}

TEST(MaxDepth, ZeroTracesNoReflectionOrRefraction) {
    // At depth 0 the reflection R is 0 (RENDERING.md §5) and a dielectric gets nothing: a Mirror is
    // then exactly a black Lambertian surface.
    RenderOptions options = smallOptions(32, 32, 4);
    options.maxDepth = 0;
    Scene blackInsteadOfMirrors = hallOfMirrors(lambertian(glm::vec3(0.0f)));
    blackInsteadOfMirrors.shaders[2] = lambertian(glm::vec3(0.0f));  // and the glass
    const BothImages mirrors = renderBoth(hallOfMirrors(mirror(0.0f)), options);
    const BothImages black = renderBoth(blackInsteadOfMirrors, options);
    const Distance cpu = distance(mirrors.cpu, black.cpu), gpu = distance(mirrors.gpu, black.gpu);
    recordRow("max depth 0 (vs mirrors and glass painted black)", cpu, gpu, distance(mirrors.gpu, mirrors.cpu));
    EXPECT_EQ(cpu.maxSteps, 0) << cpu.describe();
    EXPECT_EQ(gpu.maxSteps, 0) << gpu.describe();
}

TEST(MaxDepth, SixtyFourOnlyAddsLight) {
    // Every term of the recursion is non-negative, so allowing more bounces can only add light:
    // depth 64 >= depth 4 in every pixel and channel (up to float rounding of the sums, 1e-5).
    RenderOptions options = smallOptions(32, 32, 4);
    options.maxDepth = 4;
    const Scene scene = hallOfMirrors(mirror(0.0f));
    const BothImages shallow = renderBoth(scene, options);
    options.maxDepth = 64;
    const BothImages deep = renderBoth(scene, options);
    for (const auto& [path, pair] : {std::pair{"CPU", std::pair{&deep.cpu, &shallow.cpu}}, std::pair{"GPU", std::pair{&deep.gpu, &shallow.gpu}}})
        for (std::size_t k = 0; k < pair.first->pixels.size(); ++k)
            for (int c = 0; c < 3; ++c) ASSERT_GE(pair.first->pixels[k][c], pair.second->pixels[k][c] - 1e-5f) << path;
    const Distance d = distance(deep.gpu, deep.cpu);
    recordRow("max depth 64 (hall of mirrors)", distance(deep.cpu, shallow.cpu), distance(deep.gpu, shallow.gpu), d);
    EXPECT_TRUE(agrees(d)) << d.describe();
    EXPECT_GT(distance(deep.cpu, shallow.cpu).maxSteps, 0);  // the extra bounces are really traced
}

// ---- light intensity --------------------------------------------------------------------------

TEST(LightIntensity, ZeroLeavesOnlyTheBackground) {
    // With every light at 0 the only radiance is the background (0, 0, 0.5), seen directly or through
    // mirrors and glass: red and green are exactly 0 everywhere.
    Scene scene = invarianceScene();
    scene.background = glm::vec3(0.0f, 0.0f, 0.5f);
    for (Light& l : scene.lights) l.intensity = glm::vec3(0.0f);
    const BothImages im = renderBoth(scene, smallOptions(48, 48, 4));
    Deviation dev[2];
    for (const auto& [k, image] : {std::pair{0, &im.cpu}, std::pair{1, &im.gpu}})
        for (const glm::vec3& c : image->pixels) {
            const double light = std::max(c.x, c.y);
            dev[k].add(light, light == 0.0, std::to_string(c.x) + " " + std::to_string(c.y));
        }
    EXPECT_EQ(dev[0].wrong, 0) << "CPU: " << dev[0].first;
    EXPECT_EQ(dev[1].wrong, 0) << "GPU: " << dev[1].first;
    recordRow("light intensity 0 (red/green vs 0)", dev[0].asDistance(), dev[1].asDistance(), distance(im.gpu, im.cpu));
}

TEST(LightIntensity, AMillionScalesTheImageLinearly) {
    // No falloff and no clamping before the output: every term is proportional to I, so with a black
    // background the 1e6 image is 1e6 times the unit image, up to float rounding (1e-5 relative).
    Scene unit = invarianceScene();
    unit.background = glm::vec3(0.0f);
    Scene bright = unit;
    for (Light& l : bright.lights) l.intensity *= 1e6f;
    const RenderOptions options = smallOptions(32, 32, 4);
    const BothImages a = renderBoth(unit, options), b = renderBoth(bright, options);
    double worst = 0.0;
    Distance scaled[2];  // 8-bit distance of image(1e6) / 1e6 from image(1)
    for (int k = 0; k < 2; ++k) {
        Image down = k == 0 ? b.cpu : b.gpu;
        for (glm::vec3& c : down.pixels) c /= 1e6f;
        scaled[k] = distance(down, k == 0 ? a.cpu : a.gpu);
    }
    for (const auto& [path, pair] : {std::pair{"CPU", std::pair{&b.cpu, &a.cpu}}, std::pair{"GPU", std::pair{&b.gpu, &a.gpu}}})
        for (std::size_t k = 0; k < pair.first->pixels.size(); ++k)
            for (int c = 0; c < 3; ++c) {
                const double scaled = pair.first->pixels[k][c] / 1e6, reference = pair.second->pixels[k][c];
                const double relative = std::fabs(scaled - reference) / std::max(reference, 1e-3);
                worst = std::max(worst, relative);
                ASSERT_LE(relative, 1e-5) << path << " pixel " << k;
            }
    char name[96];
    std::snprintf(name, sizeof name, "light intensity 1e6 (image / 1e6 vs intensity 1; worst relative %.1e)", worst);
    recordRow(name, scaled[0], scaled[1], distance(b.gpu, b.cpu));
}

}  // namespace
}  // namespace vkrt::stability
