// Spheres of radius 1e-6 and 1e6, the camera inside a sphere or a box, and lights inside geometry
// (issue 7), rendered on both paths and compared with closed forms computed here in double: one ray
// per pixel centre, a Lambertian surface kd * I * max(0, N.L) with no falloff (RENDERING.md §4, §5).
#include <cmath>
#include <optional>
#include <sstream>

#include <gtest/gtest.h>

#include "both_paths.h"
#include "double_camera.h"
#include "scene_building.h"

namespace vkrt::stability {
namespace {

constexpr float kKd = 0.8f;
const glm::vec3 kSky(0.0f, 0.0f, 1.0f);

RenderOptions centreRays(int width, int height) {
    RenderOptions o = smallOptions(width, height, 1);
    o.sampler = SamplerKind::Regular;
    return o;
}

// The expected radiance of one pixel's ray, or nothing where rounding may legitimately decide
// (silhouettes, box edges).
using Expectation = std::function<std::optional<double>(const DoubleRay&)>;

// Red channel against the closed form, within 2/255 (float rounding of the camera, the hit point
// and the normal moves N.L by ~1e-6; 2/255 is the 8-bit agreement rule).
Deviation compareRed(const Image& image, const Scene& scene, int camera, const Expectation& expect) {
    Deviation r;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const DoubleRay ray = cameraRay(scene.cameras[camera], image.width, image.height, i + 0.5, j + 0.5);
            const std::optional<double> want = expect(ray);
            if (!want) continue;
            const double error = std::fabs(image.at(i, j).x - *want);
            std::ostringstream s;
            s << "pixel (" << i << "," << j << ") = " << image.at(i, j).x << ", expected " << *want;
            r.add(error, error <= 2.0 / 255.0, s.str());
        }
    return r;
}

Distance worse(const Distance& a, const Distance& b) {
    Distance w = a;
    w.maxSteps = std::max(a.maxSteps, b.maxSteps);
    w.fractionWithin2 = std::min(a.fractionWithin2, b.fractionWithin2);
    w.meanSteps = std::max(a.meanSteps, b.meanSteps);
    return w;
}

void expectClosedForm(const Scene& scene, const RenderOptions& base, const Expectation& expect, const std::string& caseName,
                      int minimumCompared) {
    Distance worstAgreement, worstCpu, worstGpu;
    for (int camera = 0; camera < static_cast<int>(scene.cameras.size()); ++camera) {
        RenderOptions options = base;
        options.camera = camera;
        const BothImages im = renderBoth(scene, options);
        for (const auto& [path, image] : {std::pair{"CPU", &im.cpu}, std::pair{"GPU", &im.gpu}}) {
            const Deviation r = compareRed(*image, scene, camera, expect);
            Distance& worst = image == &im.cpu ? worstCpu : worstGpu;
            worst = worse(worst, r.asDistance());
            EXPECT_GE(r.checked, minimumCompared) << caseName << " " << path << " camera " << camera;
            EXPECT_EQ(r.wrong, 0) << caseName << " " << path << " camera " << camera << ": " << r.first;
        }
        const Distance d = distance(im.gpu, im.cpu);
        EXPECT_TRUE(agrees(d)) << caseName << " camera " << camera << ": " << d.describe();
        worstAgreement = worse(worstAgreement, d);
    }
    recordRow(caseName + " (vs closed form)", worstCpu, worstGpu, worstAgreement);
}

// Ray/sphere in double: the two roots, if any.
std::optional<std::pair<double, double>> roots(const DoubleRay& ray, glm::dvec3 c, double r) {
    const glm::dvec3 f = ray.origin - c;
    const double b = glm::dot(f, ray.dir);
    const glm::dvec3 l = f - b * ray.dir;
    const double disc = r * r - glm::dot(l, l);
    if (disc < 0.0) return std::nullopt;
    const double s = std::sqrt(disc);
    return std::pair{-b - s, -b + s};
}

// ---- a lone sphere seen from outside ----------------------------------------------------------

class LoneSphere : public ::testing::TestWithParam<std::pair<double, glm::dvec3>> {};

TEST_P(LoneSphere, MatchesTheClosedForm) {
    const auto [r, centre] = GetParam();
    const glm::dvec3 eye = centre + r * glm::dvec3(0.0, 0.5, 4.0), light = centre + r * glm::dvec3(3.0, 4.0, 5.0);
    Scene scene;
    scene.path = "lone sphere (built in code)";
    scene.background = kSky;
    scene.cameras.push_back(perspective(glm::vec3(eye), glm::vec3(centre), 1.0f, 0.6f));
    scene.lights.push_back(pointLight(glm::vec3(light), glm::vec3(1.0f)));
    add(scene, lambertian(glm::vec3(kKd)));
    scene.shapes.push_back(sphere(glm::vec3(centre), static_cast<float>(r), 0));
    // The sphere as stored (float centre and radius) is what the image shows.
    const glm::dvec3 c(scene.shapes[0].center);
    const double radius = scene.shapes[0].radius;
    const glm::dvec3 lightAt(scene.lights[0].position);
    const Expectation expect = [&](const DoubleRay& ray) -> std::optional<double> {
        const glm::dvec3 f = ray.origin - c;
        const double miss = glm::length(f - glm::dot(f, ray.dir) * ray.dir) / radius;  // 1 at the silhouette
        if (std::fabs(miss - 1.0) < 1e-3) return std::nullopt;
        const auto t = roots(ray, c, radius);
        if (!t) return 0.0;  // the sky is (0, 0, 1): red 0
        const glm::dvec3 p = ray.origin + t->first * ray.dir;
        const glm::dvec3 n = (p - c) / radius;
        return kKd * std::max(0.0, glm::dot(n, glm::normalize(lightAt - p)));
    };
    std::ostringstream name;
    name << "lone sphere r=" << r << " centre " << centre.x;
    expectClosedForm(scene, centreRays(48, 48), expect, name.str(), 48 * 48 * 9 / 10);
}

INSTANTIATE_TEST_SUITE_P(Radii, LoneSphere,
                         ::testing::Values(std::pair{1e-6, glm::dvec3(0.0)}, std::pair{1e-6, glm::dvec3(1e-3, 2e-3, -1e-3)},
                                           std::pair{1.0, glm::dvec3(0.0)}, std::pair{1e6, glm::dvec3(0.0)},
                                           std::pair{1e6, glm::dvec3(1e9, -2e9, 1e9)}),
                         [](const auto& info) { return "Case" + std::to_string(info.index); });

// ---- the camera inside a sphere or a box ------------------------------------------------------

void addSixCameras(Scene& scene, glm::vec3 eye) {
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 gaze(0.0f);
            gaze[axis] = sign;
            scene.cameras.push_back(perspective(eye, eye + gaze, 1.0f, 2.4f));
        }
}

class CameraInsideSphere : public ::testing::TestWithParam<double> {};

TEST_P(CameraInsideSphere, SeesTheLitInsideEverywhere) {
    // The light at the centre: the inner normal, turned to the viewer, points at it, so N.L = 1 and
    // every pixel is exactly kd * I, whatever the camera sees.
    const double r = GetParam();
    Scene scene;
    scene.path = "camera inside a sphere (built in code)";
    scene.background = glm::vec3(1.0f, 0.0f, 0.0f);
    scene.lights.push_back(pointLight(glm::vec3(0.0f), glm::vec3(1.0f)));
    add(scene, lambertian(glm::vec3(kKd)));
    scene.shapes.push_back(sphere(glm::vec3(0.0f), static_cast<float>(r), 0));
    addSixCameras(scene, glm::vec3(r * glm::dvec3(0.3, -0.2, 0.1)));
    std::ostringstream name;
    name << "camera inside sphere r=" << r;
    expectClosedForm(scene, centreRays(24, 24), [](const DoubleRay&) { return std::optional<double>(kKd); }, name.str(),
                     24 * 24);
}

INSTANTIATE_TEST_SUITE_P(Radii, CameraInsideSphere, ::testing::Values(1e-6, 1.0, 1e6),
                         [](const auto& info) { return "Case" + std::to_string(info.index); });

TEST(CameraInsideBox, SeesEachInnerFaceLitByTheClosedForm) {
    const glm::dvec3 lo(-1.0, -1.0, -3.0), hi(2.0, 1.0, 1.0), light(-0.5, 0.6, 0.4);
    Scene scene;
    scene.path = "camera inside a box (built in code)";
    scene.background = glm::vec3(1.0f, 0.0f, 0.0f);
    scene.lights.push_back(pointLight(glm::vec3(light), glm::vec3(1.0f)));
    add(scene, lambertian(glm::vec3(kKd)));
    scene.shapes.push_back(box(glm::vec3(lo), glm::vec3(hi), 0));
    addSixCameras(scene, {0.2f, 0.1f, -0.3f});
    const Expectation expect = [&](const DoubleRay& ray) -> std::optional<double> {
        // From inside the ray leaves through the slab it leaves first.
        double best = INFINITY, second = INFINITY;
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            if (ray.dir[a] == 0.0) continue;
            const double t = ((ray.dir[a] > 0.0 ? hi[a] : lo[a]) - ray.origin[a]) / ray.dir[a];
            if (t < best) {
                second = best;
                best = t;
                axis = a;
            } else {
                second = std::min(second, t);
            }
        }
        if (second - best < 1e-4 * best) return std::nullopt;  // at an edge: either face
        const glm::dvec3 p = ray.origin + best * ray.dir;
        glm::dvec3 inward(0.0);
        inward[axis] = ray.dir[axis] > 0.0 ? -1.0 : 1.0;
        return kKd * std::max(0.0, glm::dot(inward, glm::normalize(light - p)));
    };
    expectClosedForm(scene, centreRays(32, 32), expect, "camera inside box", 32 * 32 * 9 / 10);
}

// ---- lights inside geometry -------------------------------------------------------------------

// A floor and a closed shell around the only light; the camera outside. Nothing outside can be lit.
Scene lightInside(Shape shell, Shader shellShader) {
    Scene scene;
    scene.path = "light inside geometry (built in code)";
    scene.background = kSky;
    scene.cameras.push_back(perspective({0.0f, 2.0f, 5.0f}, {0.0f, 0.5f, 0.0f}, 1.0f, 1.0f));
    scene.lights.push_back(pointLight({0.1f, 0.9f, -0.05f}, glm::vec3(1.0f)));
    add(scene, lambertian(glm::vec3(kKd)));
    add(scene, shellShader);
    scene.shapes.push_back(box({-5.0f, -1.0f, -5.0f}, {5.0f, 0.0f, 5.0f}, 0));
    shell.shader = 1;
    scene.shapes.push_back(shell);
    return scene;
}

// No light reaches anything: the surfaces are grey and white, the sky pure blue, so any red or green
// in a pixel is light that got out of the shell (pixels at the horizon mix sky and black floor).
void expectDark(const Scene& scene, const std::string& caseName) {
    const BothImages im = renderBoth(scene, smallOptions(40, 40, 4));
    Deviation dev[2];
    for (const auto& [k, image] : {std::pair{0, &im.cpu}, std::pair{1, &im.gpu}}) {
        int sky = 0;
        for (const glm::vec3& c : image->pixels) {
            const double light = std::max(c.x, c.y);
            dev[k].add(light, light == 0.0, "red or green " + std::to_string(light));
            sky += c == kSky ? 1 : 0;
        }
        EXPECT_EQ(dev[k].wrong, 0) << caseName << " " << (k ? "GPU" : "CPU") << ": light leaked out of the shell, " << dev[k].first;
        EXPECT_GT(sky, 0);
    }
    recordRow(caseName + " (red/green vs 0)", dev[0].asDistance(), dev[1].asDistance(), distance(im.gpu, im.cpu));
}

TEST(LightInsideGeometry, AnOpaqueSphereKeepsItIn) {
    expectDark(lightInside(sphere({0.0f, 1.0f, 0.0f}, 0.5f, 1), lambertian(glm::vec3(0.9f))), "light inside opaque sphere");
}

TEST(LightInsideGeometry, ABoxKeepsItIn) {
    expectDark(lightInside(box({-0.5f, 0.5f, -0.5f}, {0.5f, 1.5f, 0.5f}, 1), blinnPhong(glm::vec3(0.9f), glm::vec3(0.5f), 8.0f)),
               "light inside box");
}

TEST(LightInsideGeometry, AClosedMeshKeepsItIn) {
    Scene scene = lightInside(sphere({0.0f, 1.0f, 0.0f}, 0.5f, 1), lambertian(glm::vec3(0.9f)));
    scene.shapes.pop_back();
    Mesh shell = cubeSphere(12, 0.5f);
    for (glm::vec3& p : shell.positions) p += glm::vec3(0.0f, 1.0f, 0.0f);
    addLooseMesh(scene, addMesh(scene, shell), 1);
    expectDark(scene, "light inside closed mesh");
}

TEST(LightInsideGeometry, AGlassSphereBlocksItsShadowRays) {
    // RENDERING.md §4: any hit blocks a shadow ray, dielectrics too.
    expectDark(lightInside(sphere({0.0f, 1.0f, 0.0f}, 0.5f, 1), dielectric(1.5f)), "light inside glass sphere");
}

TEST(LightOnASurface, IsNotShadowedByTheSurfaceItSitsOn) {
    // An area light lying exactly on the lower face of a ceiling panel (a Cornell box's lamp): the
    // shadow ray ends 2^-16 short of the light (RENDERING.md §4), so the panel does not block it. The
    // camera looks straight down at the floor under the lamp, within 0.4 of its centre: every light
    // sample arrives with N.L >= 2 / |(0.9, 2, 0.9)| > 0.8, so every pixel is above 0.8 kd.
    Scene scene;
    scene.path = "light on a ceiling (built in code)";
    scene.background = kSky;
    scene.cameras.push_back(perspective({0.0f, 1.5f, 0.0f}, {0.0f, 0.0f, 0.0f}, 1.0f, 0.5f));
    scene.lights.push_back(areaLight({0.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 1.0f, 1.0f, glm::vec3(1.0f)));
    add(scene, lambertian(glm::vec3(kKd)));
    scene.shapes.push_back(box({-5.0f, -1.0f, -5.0f}, {5.0f, 0.0f, 5.0f}, 0));
    scene.shapes.push_back(box({-3.0f, 2.0f, -3.0f}, {3.0f, 2.5f, 3.0f}, 0));
    RenderOptions options = smallOptions(32, 32, 4);
    options.lightSamples = 4;
    const BothImages im = renderBoth(scene, options);
    Deviation dev[2];
    for (const auto& [k, image] : {std::pair{0, &im.cpu}, std::pair{1, &im.gpu}})
        for (const glm::vec3& c : image->pixels) {
            const double shortfall = std::max(0.0, kKd * 0.8 - c.x);
            dev[k].add(shortfall, shortfall == 0.0, "red " + std::to_string(c.x));
        }
    EXPECT_EQ(dev[0].wrong, 0) << "CPU: " << dev[0].first;
    EXPECT_EQ(dev[1].wrong, 0) << "GPU: " << dev[1].first;
    const Distance d = distance(im.gpu, im.cpu);
    recordRow("area light on a ceiling panel (shortfall below 0.8 kd)", dev[0].asDistance(), dev[1].asDistance(), d);
    EXPECT_TRUE(agrees(d)) << d.describe();
}

}  // namespace
}  // namespace vkrt::stability
