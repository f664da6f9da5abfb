// Shape emitters (issue 20, docs/RENDERING.md §4) lighting a plane, on both devices, against the
// closed forms of radiometry computed here (path_tracing_support.h), never against the renderers:
//   - a sphere of radius r and radiance L wholly above a Lambertian plane gives kd L (r/d)^2 cos
//     per pixel, and so does a Diffuse plane at max depth 1 under a black sky, under every
//     estimator; a sphere of radius 1e-3 with L r^2 kept is the same falloff point source;
//   - the same sphere as a world sphere, as an instance of the unit sphere (uniform scale and
//     translation) and mirrored (negative scale) lights the plane alike; an ellipsoid (non-uniform
//     scale) lights it as Lambert's integral over its silhouette says, by light samples (Nanson's
//     area density) and by bounces alike;
//   - a quad of two triangles (world space, non-uniformly scaled and tilted, mirrored) lights it
//     as Lambert's polygon formula says, from either side (emission is two-sided); a box (rotated,
//     mirrored, non-uniformly scaled) as the formula summed over the faces in front of each point;
//   - the two devices agree by the project's rule on every image.
// The plane is the top face of a box, seen from a camera below every emitter (top view at height
// 0.5, every emitter above), so no pixel sees an emitter and every pixel is the receiver.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "both_paths.h"
#include "path_tracing_support.h"
#include "scene_loader.h"
#include "scene_building.h"

namespace vkrt::stability {
namespace {

constexpr int kSize = 24;          // pixels across the 3 x 3 square of plane seen
constexpr float kHalf = 1.5f;
constexpr float kCameraHeight = 0.5f;
const glm::vec3 kKd(0.8f, 0.6f, 0.4f);
// Each render is one family of 24 x 24 x 3 values; a false failure anywhere in it has probability
// 1e-3 (Sidak), |z| ~ 5.0.
const double kZ = zLimitFor(kSize * kSize * 3, 1e-3);
// Relative floor of the per-pixel tolerance: the renderers' float arithmetic (a light sample's
// direction and density to ~1e-6 relative, 256 samples summed in float: ~1e-5) and the closed
// forms' quadrature (< 1e-5); a wrong convention (a missing cosine, pi, or falloff) is > 10%.
constexpr double kFloor = 1e-4;

const Estimator kAllEstimators[] = {Estimator::Bounce, Estimator::Nee, Estimator::MisBalance, Estimator::MisPower};

// The plane y = 0 under the camera, its shader `receiver`, a black sky: add emitters.
Scene plane(const Shader& receiver) {
    Scene scene;
    scene.path = "a plane under shape emitters (built in code)";
    scene.background = glm::vec3(0.0f);
    scene.cameras.push_back(topView(kHalf, kCameraHeight));
    scene.shapes.push_back(box({-6.0f, -1.0f, -6.0f}, {6.0f, 0.0f, 6.0f}, add(scene, receiver)));
    return scene;
}

// kd L / pi times an emitter's cosine integral at each plane point: the reflected radiance.
PlaneRadiance reflected(glm::vec3 radiance, const std::function<double(glm::dvec3)>& cosineIntegral) {
    return [=](glm::dvec3 p) { return glm::dvec3(kKd) * glm::dvec3(radiance) * cosineIntegral(p) / std::numbers::pi; };
}

struct Rendered {
    BothImages images;
    Image variance;  // the CPU's per-pixel sample variance
    int rpp = 0;
};

Rendered render(const Scene& scene, const RenderOptions& options) {
    Rendered r;
    r.images = renderBoth(scene, options, &r.variance);
    r.rpp = options.samplesPerPixel;
    return r;
}

// Both devices' images against the exact image, per pixel (block 1) or per block, and the whole
// region's mean; then the devices against each other by the project's rule.
void expectMatches(const Rendered& r, const Image& expected, const std::string& what, int block = 1) {
    const double z = block == 1 ? kZ : zLimitFor((kSize / block) * (kSize / block) * 3, 1e-3);
    for (const auto& [device, image] : {std::pair{"CPU", &r.images.cpu}, std::pair{"GPU", &r.images.gpu}}) {
        const NoiseComparison c = compareWithNoise({image, &r.variance, r.rpp}, {&expected}, block, z, kFloor);
        recordNote(what + " (" + device + ")", c.describe());
        EXPECT_EQ(c.failing, 0) << what << ", " << device << ": " << c.describe();
        // The whole region's mean: a bias of a few tenths of a percent shows here.
        EXPECT_LT(std::fabs(c.meanZ), zLimitFor(1, 1e-3)) << what << ", " << device << ": " << c.describe();
    }
    const Distance d = distance(r.images.gpu, r.images.cpu);
    recordRow(what, d);
    EXPECT_TRUE(agrees(d)) << what << ": GPU vs CPU " << d.describe();
}

// The receivers a closed form is checked on: a Lambertian plane (light samples of the emitter,
// never weighted: §5), and a Diffuse plane at max depth 1 under a black sky (its bounce finds only
// the emitter, so it reflects exactly the same light) under each estimator. The bounce estimator
// finds a small emitter with a few samples per pixel ((r/d)^2 cos, ~7% at the centre and 0.5% at
// the corners here), so it gets 4x the samples and is judged over 4 x 4 pixel blocks, where 4,096
// samples hold 20 hits or more even at the corners. The balance heuristic is judged over 2 x 2
// blocks: where the light samples are near-exact (a quad sampled by solid angle) its noise is the
// few bounce hits a pixel gets (~6 of 64 samples, each weighed ~p_b / (p_b + p_l)), and a pixel
// with 2 hits has both a low mean and a low sample variance, so its z is no Gaussian (measured:
// z 7.3 at one pixel whose mean over 12 seeds is 1.1% from the closed form, z 1.8); a block
// of four holds ~25 hits.
void expectEveryReceiverMatches(const Scene& lambertianScene, const Scene& diffuseScene, const Image& expected,
                                const std::string& what, int rpp, bool withBounce = true) {
    expectMatches(render(lambertianScene, pathOptions(kSize, rpp, 4, Estimator::MisPower)), expected, what + ", Lambertian");
    for (Estimator e : kAllEstimators) {
        if (e == Estimator::Bounce && !withBounce) continue;
        const bool bounce = e == Estimator::Bounce;
        expectMatches(render(diffuseScene, pathOptions(kSize, bounce ? 4 * rpp : rpp, 1, e)), expected,
                      what + ", Diffuse at depth 1, " + estimatorName(e), bounce ? 4 : e == Estimator::MisBalance ? 2 : 1);
    }
}

// ---- a sphere ----
// Bug targeted: any other falloff or cosine convention (the course's no-falloff point light, a
// missing receiver cosine, an emitter radiance off by pi), a cone density that is not 1 / solid
// angle, a bounce that sees the emitter at another radiance than the light samples count.
const glm::vec3 kCentre(0.2f, 1.1f, -0.1f);
constexpr float kRadius = 0.3f;
const glm::vec3 kRadiance(2.0f, 3.0f, 4.0f);

PlaneRadiance sphereLight(glm::vec3 centre, float radius, glm::vec3 radiance) {
    return reflected(radiance, [=](glm::dvec3 p) { return sphereCosineIntegral(p, {0, 1, 0}, centre, radius); });
}

TEST(Emitters, ASphereLightsAPlaneAsRSquaredOverDSquaredTimesTheCosine) {
    Scene lambertianPlane = plane(lambertian(kKd)), diffusePlane = plane(diffuse(kKd));
    for (Scene* s : {&lambertianPlane, &diffusePlane}) addSphereEmitter(*s, kCentre, kRadius, kRadiance);
    const Image expected = expectedTopView(kSize, kHalf, sphereLight(kCentre, kRadius, kRadiance));
    expectEveryReceiverMatches(lambertianPlane, diffusePlane, expected, "sphere r 0.3 at height 1.1", 64);
}

// The 0-radius limit (§4): a sphere of radius 1e-3 with L r^2 kept is a point source of intensity
// pi r^2 L with inverse-square falloff, so the same formula holds. Its cone is 1e-3 rad wide:
// 1 - cos(alpha) ~ 5e-7 is 8 float steps below 1, so a solid angle computed as 2 pi (1 - cos)
// from a float cosine is off by ~10%. The bounce estimator cannot find it (a hit per 10^6
// samples) and is not asked to.
TEST(Emitters, ATinySphereIsAPointSourceWithInverseSquareFalloff) {
    constexpr float tiny = 1e-3f;
    const glm::vec3 radiance = kRadiance * (kRadius / tiny) * (kRadius / tiny);
    Scene lambertianPlane = plane(lambertian(kKd)), diffusePlane = plane(diffuse(kKd));
    for (Scene* s : {&lambertianPlane, &diffusePlane}) addSphereEmitter(*s, kCentre, tiny, radiance);
    const Image expected = expectedTopView(kSize, kHalf, sphereLight(kCentre, tiny, radiance));
    expectEveryReceiverMatches(lambertianPlane, diffusePlane, expected, "sphere r 1e-3 at height 1.1", 16, false);
}

// ---- the sphere under transforms ----
// Bug targeted: a cone or density computed from the object-space radius (the prototype's 1) or
// from a signed scale (a mirroring transform's det < 0, a negative radius), a similarity taken for
// an ellipsoid or the reverse.
TEST(Emitters, AnInstancedOrMirroredUnitSphereLightsAsTheWorldSphere) {
    const glm::mat4 place = glm::translate(glm::mat4(1.0f), kCentre);
    struct Case {
        const char* name;
        glm::mat4 toWorld;
    };
    const Image expected = expectedTopView(kSize, kHalf, sphereLight(kCentre, kRadius, kRadiance));
    for (const Case& k : {Case{"unit sphere scaled by 0.3", glm::scale(place, glm::vec3(kRadius))},
                          Case{"unit sphere scaled by -0.3", glm::scale(place, glm::vec3(-kRadius))},
                          Case{"unit sphere turned and scaled by (0.3, -0.3, 0.3)",
                               glm::scale(glm::rotate(place, 0.7f, glm::vec3(1, 2, 3)), glm::vec3(kRadius, -kRadius, kRadius))}}) {
        SCOPED_TRACE(k.name);
        Scene lambertianPlane = plane(lambertian(kKd)), diffusePlane = plane(diffuse(kKd));
        for (Scene* s : {&lambertianPlane, &diffusePlane}) addPlacedEmitter(*s, sphere({0, 0, 0}, 1.0f, -1), k.toWorld, kRadiance);
        expectMatches(render(lambertianPlane, pathOptions(kSize, 64, 4, Estimator::MisPower)), expected,
                      std::string(k.name) + ", Lambertian");
        expectMatches(render(diffusePlane, pathOptions(kSize, 64, 1, Estimator::MisPower)), expected,
                      std::string(k.name) + ", Diffuse at depth 1, mis");
    }
}

// An ellipsoid: sampled by area with Nanson's density (§4), found by bounces as geometry; both
// must give Lambert's integral over its silhouette (512 corners: the inscribed polygon misses
// 2.5e-5 of it), and so each other. Its lowest point is above the camera (height >= 0.75).
TEST(Emitters, AnEllipsoidLightsAsLambertsIntegralOverItsSilhouette) {
    const glm::mat4 turned = glm::rotate(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 1.2f, 0.1f)), 0.5f,
                                                     glm::vec3(0, 1, 0)),
                                         0.4f, glm::vec3(1, 0, 0));
    for (const glm::vec3 scale : {glm::vec3(0.45f, 0.15f, 0.3f), glm::vec3(-0.45f, 0.15f, 0.3f)}) {
        const glm::mat4 toWorld = glm::scale(turned, scale);
        const std::string name = "ellipsoid scaled by (" + std::to_string(scale.x).substr(0, 5) + ", 0.15, 0.3)";
        SCOPED_TRACE(name);
        const glm::dmat4 m(toWorld);
        const Image expected = expectedTopView(
            kSize, kHalf,
            reflected(kRadiance, [&](glm::dvec3 p) { return polygonCosineIntegral(p, {0, 1, 0}, ellipsoidSilhouette(p, m, 512)); }),
            4);
        Scene lambertianPlane = plane(lambertian(kKd)), diffusePlane = plane(diffuse(kKd));
        for (Scene* s : {&lambertianPlane, &diffusePlane}) addPlacedEmitter(*s, sphere({0, 0, 0}, 1.0f, -1), toWorld, kRadiance);
        expectEveryReceiverMatches(lambertianPlane, diffusePlane, expected, name, 64);
        // Light samples against bounces directly, over 4 x 4 blocks: they must agree in
        // expectation whatever the closed form says.
        const Rendered nee = render(diffusePlane, pathOptions(kSize, 64, 1, Estimator::Nee));
        const Rendered bounce = render(diffusePlane, pathOptions(kSize, 256, 1, Estimator::Bounce));
        for (const auto& [device, a, b] : {std::tuple{"CPU", &nee.images.cpu, &bounce.images.cpu},
                                           std::tuple{"GPU", &nee.images.gpu, &bounce.images.gpu}}) {
            const NoiseComparison c = compareWithNoise({a, &nee.variance, nee.rpp}, {b, &bounce.variance, bounce.rpp}, 4,
                                                       zLimitFor(36 * 3, 1e-3), kFloor);
            recordNote(name + ", nee against bounce (" + device + ")", c.describe());
            EXPECT_EQ(c.failing, 0) << device << ": " << c.describe();
        }
    }
}

// ---- a quad of two triangles ----
// Bug targeted: one-sided emission (the world quad's triangles face up, away from the plane),
// a triangle density from object-space areas (a non-uniform scale changes the area), a mirrored
// mesh's flipped winding taken for a flipped side.
TEST(Emitters, AQuadMeshLightsAsLambertsPolygonFormulaSays) {
    const glm::mat4 lifted = glm::translate(glm::mat4(1.0f), glm::vec3(-0.1f, 1.1f, 0.15f));
    struct Case {
        const char* name;
        glm::mat4 toWorld;
    };
    for (const Case& k : {Case{"quad 0.8 x 0.6 facing away from the plane", glm::scale(lifted, glm::vec3(0.8f, 1.0f, 0.6f))},
                          Case{"quad tilted 30 degrees, scaled by (1.2, 2, 0.5)",
                               glm::scale(glm::rotate(lifted, 0.52f, glm::vec3(1, 0, 0.3f)), glm::vec3(1.2f, 2.0f, 0.5f))},
                          Case{"quad mirrored, scaled by (-0.9, 1, 0.7)", glm::scale(lifted, glm::vec3(-0.9f, 1.0f, 0.7f))}}) {
        SCOPED_TRACE(k.name);
        std::vector<glm::dvec3> corners;
        for (const glm::vec3& c : unitQuad().positions) corners.push_back(glm::dvec3(k.toWorld * glm::vec4(c, 1.0f)));
        for (const glm::dvec3& c : corners) ASSERT_GT(c.y, kCameraHeight) << "the camera would see the emitter";
        const Image expected = expectedTopView(
            kSize, kHalf, reflected(kRadiance, [&](glm::dvec3 p) { return polygonCosineIntegral(p, {0, 1, 0}, corners); }));
        Scene lambertianPlane = plane(lambertian(kKd)), diffusePlane = plane(diffuse(kKd));
        for (Scene* s : {&lambertianPlane, &diffusePlane}) addPlacedEmitter(*s, meshShape(addMesh(*s, unitQuad())), k.toWorld, kRadiance);
        expectEveryReceiverMatches(lambertianPlane, diffusePlane, expected, k.name, 64);
    }
}

// ---- a box ----
// Seen from a plane point, a convex box shows the faces whose plane the point is in front of, and
// those are where its light samples go (emitter_sampling.h triangleFacesPoint): the reflected light
// is Lambert's polygon formula summed over them.
// Bug targeted: samples on the hidden faces counted (or their density left in: 2x too dark), a
// mirrored box's winding taken for the outside (the hidden faces sampled: black), a bounce's hit
// weighed with another density than the light samples'.
TEST(Emitters, ABoxLightsAsLambertsFormulaOverTheFacesInFrontOfEachPoint) {
    const glm::mat4 toWorld =
        glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 1.3f, -0.05f)), 0.6f, glm::vec3(1.0f, 0.4f, -0.3f)),
                   glm::vec3(-0.5f, 0.3f, 0.6f));
    // The six faces of [-0.5, 0.5]^3 in the world, each a convex quad in cyclic order, with a point
    // inside the box to orient them.
    std::vector<std::vector<glm::dvec3>> faces;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-0.5f, 0.5f}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            std::vector<glm::dvec3> quad;
            for (glm::vec2 c : {glm::vec2(-0.5f, -0.5f), glm::vec2(0.5f, -0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(-0.5f, 0.5f)}) {
                glm::vec3 p(0.0f);
                p[axis] = side, p[u] = c.x, p[v] = c.y;
                quad.push_back(glm::dvec3(toWorld * glm::vec4(p, 1.0f)));
                ASSERT_GT(quad.back().y, kCameraHeight) << "the camera would see the emitter";
            }
            faces.push_back(quad);
        }
    const glm::dvec3 centre(toWorld * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    const auto inFront = [&](const std::vector<glm::dvec3>& f, glm::dvec3 p) {
        glm::dvec3 n = glm::cross(f[1] - f[0], f[3] - f[0]);
        if (glm::dot(n, centre - f[0]) > 0.0) n = -n;  // outwards
        return glm::dot(n, p - f[0]) > 0.0;
    };
    const Image expected = expectedTopView(kSize, kHalf, reflected(kRadiance, [&](glm::dvec3 p) {
        double sum = 0.0;
        for (const std::vector<glm::dvec3>& f : faces)
            if (inFront(f, p)) sum += polygonCosineIntegral(p, {0, 1, 0}, f);
        return sum;
    }));
    Scene lambertianPlane = plane(lambertian(kKd)), diffusePlane = plane(diffuse(kKd));
    for (Scene* s : {&lambertianPlane, &diffusePlane})
        addPlacedEmitter(*s, box({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, -1), toWorld, kRadiance);
    expectEveryReceiverMatches(lambertianPlane, diffusePlane, expected, "box rotated, scaled by (-0.5, 0.3, 0.6)", 64);
}

// The closed forms' own check: Lambert's polygon integral over a sphere's silhouette (an
// ellipsoid that is a sphere) is the sphere's pi (r/d)^2 cos, at points near and far.
TEST(Emitters, TheSilhouetteIntegralOfASphereIsItsClosedForm) {
    const glm::dmat4 m = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(kCentre)), glm::dvec3(kRadius));
    for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(1.4, 0, -1.5), glm::dvec3(-1.5, 0, 1.5)}) {
        const double exact = sphereCosineIntegral(p, {0, 1, 0}, glm::dvec3(kCentre), kRadius);
        const double polygon = polygonCosineIntegral(p, {0, 1, 0}, ellipsoidSilhouette(p, m, 512));
        EXPECT_NEAR(polygon / exact, 1.0, 5e-5) << p.x << ", " << p.z;
    }
}

}  // namespace
}  // namespace vkrt::stability

namespace vkrt::stability {
namespace {

// The JSON `Emitter` shader (issue 37: it rendered as black Lambertian): a sphere whose shader is
// an Emitter of emission c, and a box instance with one, render exactly as the same geometry
// given as `shape` lights of intensity c (the identity the loader's rule states,
// shader_emitters.h), bit for bit on each device, lighting a Diffuse floor; and the devices agree.
Scene loadJsonScene(const std::string& name, const std::string& body) {
    const std::filesystem::path dir = std::filesystem::current_path() / "test_artifacts" / "emitter_shader";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path) << "{\"scene\": {\n"
                           R"("camera": [{"_name": "main", "_type": "perspective", "position": "0 3 6", "lookatPoint": "0 0 0", "focalLength": 1, "imagePlaneWidth": 1.2}],)"
                           "\n" << body << "\n}}\n";
    LoadOptions options{false, /*localOrigin=*/true};
    options.shaderEmitters = true;
    Diagnostics diagnostics;
    return loadScene(path, options, diagnostics);
}

TEST(EmitterShader, RendersAsTheSameShapeLightsOnBothDevices) {
    const std::string shaders = R"("shader": [{"_name": "floor", "_type": "Diffuse", "diffuse": "0.7 0.7 0.7"},)"
                                R"( {"_name": "lamp", "_type": "Emitter", "emission": "4 3 2"}],)";
    const std::string floor = R"({"_type": "box", "_name": "floor", "minPt": "-5 -1 -5", "maxPt": "5 0 5", "shader": {"_ref": "floor"}})";
    const std::string panel = R"("instance": [{"_name": "panel", "_type": "box", "minPt": "-0.5 0 -0.5", "maxPt": "0.5 0.1 0.5", "shader": {"_ref": "floor"}}],)";
    const Scene byShader = loadJsonScene("by_shader.json", shaders + "\n" + panel + "\n" +
        R"("shape": [)" + floor + R"(, {"_type": "sphere", "_name": "bulb", "center": "-1 1 0", "radius": 0.4, "shader": {"_ref": "lamp"}},)" +
        R"( {"_type": "instance", "_name": "p", "_id": "panel", "shader": {"_ref": "lamp"}, "xform": [{"type": "translate", "amount": "1.2 1 0"}]}])");
    const Scene byLight = loadJsonScene("by_light.json", shaders + "\n" + panel + "\n" +
        R"("shape": [)" + floor + R"(],)" + "\n" +
        R"("light": [{"_type": "shape", "intensity": "4 3 2", "shape": {"_type": "sphere", "_name": "bulb", "center": "-1 1 0", "radius": 0.4, "shader": {"_ref": "lamp"}}},)" +
        R"( {"_type": "shape", "intensity": "4 3 2", "shape": {"_type": "instance", "_name": "p", "_id": "panel", "shader": {"_ref": "lamp"}, "xform": [{"type": "translate", "amount": "1.2 1 0"}]}}])");
    ASSERT_EQ(byShader.emitters.size(), 2u);
    const RenderOptions options = pathOptions(32, 16, 3, Estimator::MisPower);
    const BothImages a = renderBoth(byShader, options), b = renderBoth(byLight, options);
    expectSameGpuImage(a.gpu, b.gpu, "Emitter shader vs shape light (GPU)");
    for (std::size_t i = 0; i < a.cpu.pixels.size(); ++i) ASSERT_EQ(a.cpu.pixels[i], b.cpu.pixels[i]) << "CPU pixel " << i;
    double lit = 0.0;  // the floor is lit: not the black it was when the shader was a fallback
    for (const glm::vec3& p : a.cpu.pixels) lit += p.x;
    EXPECT_GT(lit / static_cast<double>(a.cpu.pixels.size()), 0.05);
    const Distance d = distance(a.gpu, a.cpu);
    EXPECT_TRUE(agrees(d)) << d.describe();
}

}  // namespace
}  // namespace vkrt::stability
