// The instructor's reference renders (../shared/scenes/upstream/reference/, README.md there):
// each is rendered with the scene that made it at 250x250, 16 jittered rpp, background 50/255,
// and compared in 8-bit values. Requirement: >= 99% of non-edge pixels within 2/255, where
// non-edge means the reference's 3x3 neighbourhood spans at most 12/255 in every channel (jittered
// silhouettes cannot match pixel for pixel). The two special cases follow the README:
//  - simpleTwoSpheres.png was made from an unpublished variant: the same geometry with the lights
//    coloured (1,0,0), (0,0.8,0), (0,0,0.25) and a black background; built here from the file.
//  - simpleTwoSpheres_MirroredFloor.png was made from simpleSphereScene_MirroredFloor.xml (glossy
//    floor, roughness 0.5) with many random samples: its noise cannot match pixel for pixel, so
//    the means of 5x5 blocks are compared instead, with the same non-edge rule and 2/255 plus three
//    standard errors of the difference of the two block means (the reference's own noise is ~10/255
//    per pixel in the blurred sphere reflections). One convention is not pinned by the course: a
//    glossy direction that falls below the floor. vkrt makes it black (RENDERING.md §5); the
//    reference is brighter there (measured: as if about half of those samples saw the background).
//    That only matters where the lecture's square of directions around the mirror direction crosses
//    the floor, i.e. the floor near the horizon; those blocks are computed from the camera and
//    the roughness, excluded from the requirement, reported separately, and required to be no
//    brighter than the reference (black is the least a sample can contribute).
//
// The JSON twins of those scenes (../shared/scenes/json, SOURCES.md there: the same camera,
// lights, shaders and shapes as the XML that made the render) meet the same requirement against
// the same image (suite JsonTwins). A scene named with .json is read from the JSON folder.
#include <chrono>
#include <cmath>
#include <functional>
#include <cstdio>
#include <string>
#include <vector>

#include <ostream>

#include <gtest/gtest.h>

#include "analytic_scene.h"
#include "image_compare.h"
#include "scene_accel.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

struct Reference {
    const char* image;  // in reference/
    const char* scene;  // in upstream/, or in ../json/ when it ends with .json
    enum Kind { Plain, RecolouredLights, BlockMeans } kind = Plain;
};

// Names the case in ctest's list (gtest would print the struct's bytes).
void PrintTo(const Reference& r, std::ostream* os) { *os << r.image << " from " << r.scene; }

const Reference kReferences[] = {
    {"oneSphere", "oneSphere.xml"},
    {"oneTriangle", "oneTriangle.xml"},
    {"threeTriangles", "threeTriangles.xml"},
    {"oneBox", "sd2019_oneBox.xml"},
    {"lambertianChalkSpheres", "lambertianChalkSpheres.xml"},
    {"PhongExp", "PhongExp.xml"},
    {"simpleTwoSpheres_GlazedFloor", "simpleTwoSpheres_GlazedFloor.xml"},
    {"mirrorTest", "mirrorTest.xml"},
    {"mirrorTest2", "mirrorTest2.xml"},
    {"mirroredScene", "mirroredScene.xml"},
    {"CornellRoom_wMirroredSpheres", "CornellRoom_wMirroredSpheres.xml"},
    {"boxSphereTest", "boxSphereTest.xml"},
    {"spheres_1K", "spheres_1K.xml"},
    {"simpleTwoSpheres", "simpleTwoSpheres.xml", Reference::RecolouredLights},
    {"simpleTwoSpheres_MirroredFloor", "simpleSphereScene_MirroredFloor.xml", Reference::BlockMeans},
};

// The JSON twins with a reference (SOURCES.md, "Reference renders"; the loader's JsonTwins test
// checks each scene model against its XML field by field, tests/agreement the images bit for bit).
// Backgrounds may differ from the XML's (mirrorScene01, sd20190224_spheres_1K): the references'
// 50/255 overrides both. oneBox.json holds sd2019_oneBox.xml (camera at -8 4 4), which made
// oneBox.png by upstream/reference/README.md's measurement (0.997 vs 0.685 for oneBox.xml);
// SOURCES.md's note that oneBox.json does not match oneBox.png assumes the 2018 camera instead.
// Rendered on the CPU, as the XML side; the GPU image of each twin equals its XML's bit for bit.
const Reference kJsonTwinReferences[] = {
    {"oneSphere", "oneSphere.json"},
    {"oneTriangle", "oneTriangle.json"},
    {"threeTriangles", "threeTriangles.json"},
    {"threeTriangles", "sd20180202_threeTriangles.json"},
    {"oneBox", "oneBox.json"},
    {"lambertianChalkSpheres", "lambertianChalkSpheres.json"},
    {"PhongExp", "PhongExp.json"},
    {"mirrorTest", "sd20190227_mirrorScene00.json"},
    {"mirrorTest2", "mirrorScene01.json"},
    {"spheres_1K", "sd20190224_spheres_1K.json"},
};

bool isJson(const Reference& r) { return std::string(r.scene).ends_with(".json"); }

// The case's name: the image for the XML scenes, the scene file's stem for the JSON twins (two
// JSON files share threeTriangles.png).
std::string caseName(const Reference& r) {
    const std::string scene = r.scene;
    return isJson(r) ? scene.substr(0, scene.size() - 5) : std::string(r.image);
}

constexpr int kSize = 250;
constexpr int kEdgeSpan = 12;   // 8-bit steps: a reference 3x3 neighbourhood wider than this is an edge
constexpr int kTolerance = 2;   // 8-bit steps
constexpr double kRequired = 0.99;

// 8-bit channel values, row-major, 3 per pixel.
struct Bytes {
    int width = 0, height = 0;
    std::vector<int> v;
    int at(int x, int y, int c) const { return v[(static_cast<std::size_t>(y) * width + x) * 3 + c]; }
};

Bytes toBytes(const Image& image, bool fromFile) {
    Bytes b{image.width, image.height, {}};
    b.v.reserve(image.pixels.size() * 3);
    for (const glm::vec3& p : image.pixels)
        for (int c = 0; c < 3; ++c)
            // A file read back gives value/255 exactly representable up to rounding; a render is
            // quantised with the course's clamp-and-truncate rule.
            b.v.push_back(fromFile ? static_cast<int>(std::lround(p[c] * 255.0f)) : quantize8(p[c]));
    return b;
}

// Means of block x block squares (5x5 for the glossy reference), rounded to 8-bit units, and the
// variance of each mean (sample variance of the block's pixels / pixel count).
struct BlockMeans {
    Bytes means;
    std::vector<double> varianceOfMean;  // per block and channel
};

BlockMeans blockMeans(const Bytes& in, int block) {
    BlockMeans out{{in.width / block, in.height / block, {}}, {}};
    const int n = block * block;
    for (int by = 0; by < out.means.height; ++by)
        for (int bx = 0; bx < out.means.width; ++bx)
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0, sum2 = 0.0;
                for (int y = 0; y < block; ++y)
                    for (int x = 0; x < block; ++x) {
                        const double v = in.at(bx * block + x, by * block + y, c);
                        sum += v;
                        sum2 += v * v;
                    }
                const double mean = sum / n;
                out.means.v.push_back(static_cast<int>(std::lround(mean)));
                out.varianceOfMean.push_back(std::max(0.0, (sum2 - n * mean * mean) / (n - 1)) / n);
            }
    return out;
}

// Blocks whose pixels see the glossy floor (the top y = floorY of a box with a rough shader) at a
// point where some direction of the lecture's square (side = roughness, in the (U, V') basis of
// RENDERING.md §5) points below the floor. Computed per pixel centre in double from the camera.
std::vector<bool> grazingGlossBlocks(const Scene& scene, const RenderOptions& options, int block) {
    float roughness = 0.0f, floorY = 0.0f;
    for (const Shape& shape : scene.shapes)
        if (shape.type == ShapeType::Box && scene.shaders[shape.shader].roughness > roughness) {
            roughness = scene.shaders[shape.shader].roughness;
            floorY = shape.maxPt.y;
        }
    const DCamera cam = makeDCamera(scene.cameras[0], options.width, options.height);
    const int bw = options.width / block;
    std::vector<bool> grazing(static_cast<std::size_t>(bw) * (options.height / block), false);
    if (roughness <= 0.0f) return grazing;
    for (int j = 0; j < options.height; ++j)
        for (int i = 0; i < options.width; ++i) {
            const DRay ray = dcameraRay(cam, i + 0.5, j + 0.5);
            if (!(ray.dir.y < 0.0) || ray.origin.y <= floorY) continue;  // does not reach the floor from above
            const glm::dvec3 r(ray.dir.x, -ray.dir.y, ray.dir.z);        // mirror direction off y = floorY
            const glm::dvec3 a = glm::abs(r);
            const glm::dvec3 axis = (a.x <= a.y && a.x <= a.z) ? glm::dvec3(1, 0, 0)
                                    : (a.y <= a.z ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1));
            const glm::dvec3 u = glm::normalize(glm::cross(r, axis));
            const glm::dvec3 v = glm::cross(r, u);
            const double lowest = r.y - 0.5 * roughness * (std::abs(u.y) + std::abs(v.y));
            if (lowest <= 0.0 && j / block < options.height / block && i / block < bw)
                grazing[static_cast<std::size_t>(j / block) * bw + i / block] = true;
        }
    return grazing;
}

struct Score {
    int excluded = 0;            // grazing glossy blocks (see above), not in nonEdge
    double excludedNotBrighter = 1.0;  // fraction of them not brighter than the reference beyond tolerance
    double excludedWithin = 1.0;
    int nonEdge = 0;
    double nonEdgeWithin = 0.0;  // fraction of non-edge pixels within kTolerance
    double allWithin = 0.0;      // fraction of all pixels within kTolerance
};

// Per compared unit (pixel or block) and channel, the allowed difference in 8-bit steps.
using ToleranceFn = std::function<double(int x, int y, int c)>;

Score score(const Bytes& ours, const Bytes& ref, const ToleranceFn& tolerance, const std::vector<bool>& exclude) {
    Score s;
    int nonEdgeOk = 0, allOk = 0, excludedOk = 0, excludedNotBrighter = 0;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            bool within = true, notBrighter = true, edge = false;
            for (int c = 0; c < 3; ++c) {
                const int diff = ours.at(x, y, c) - ref.at(x, y, c);
                within = within && std::abs(diff) <= tolerance(x, y, c);
                notBrighter = notBrighter && diff <= tolerance(x, y, c);
                int lo = 255, hi = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int xx = x + dx, yy = y + dy;
                        if (xx < 0 || yy < 0 || xx >= ref.width || yy >= ref.height) continue;
                        lo = std::min(lo, ref.at(xx, yy, c));
                        hi = std::max(hi, ref.at(xx, yy, c));
                    }
                edge = edge || hi - lo > kEdgeSpan;
            }
            allOk += within;
            if (!exclude.empty() && exclude[static_cast<std::size_t>(y) * ref.width + x]) {
                ++s.excluded;
                excludedOk += within;
                excludedNotBrighter += notBrighter;
            } else if (!edge) {
                ++s.nonEdge;
                nonEdgeOk += within;
            }
        }
    s.nonEdgeWithin = s.nonEdge ? double(nonEdgeOk) / s.nonEdge : 0.0;
    s.allWithin = double(allOk) / (ref.width * ref.height);
    if (s.excluded) {
        s.excludedWithin = double(excludedOk) / s.excluded;
        s.excludedNotBrighter = double(excludedNotBrighter) / s.excluded;
    }
    return s;
}

class ReferenceRender : public ::testing::TestWithParam<Reference> {};

TEST_P(ReferenceRender, AgreesWithTheInstructorsImage) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    const Reference& r = GetParam();
    const std::string dir = upstreamDir();
    const std::string sceneDir = isJson(r) ? jsonSceneDir() : dir;
    VKRT_SKIP_WITHOUT(sceneDir);
    Diagnostics diagnostics;
    Scene scene = loadScene(sceneDir + "/" + r.scene, LoadOptions{}, diagnostics);

    RenderOptions options;
    options.width = kSize;
    options.height = kSize;
    options.samplesPerPixel = 16;
    // `--look reference`: the 50/255 background, and no environment map (mirrorTest2.xml names
    // data/reef_; the course's code that made the references never sampled one, JSON_FORMAT.md §5.1).
    applyReferenceLook(options);
    if (r.kind == Reference::RecolouredLights) {
        const glm::vec3 colours[] = {{1, 0, 0}, {0, 0.8f, 0}, {0, 0, 0.25f}};
        ASSERT_EQ(scene.lights.size(), 3u) << "simpleTwoSpheres.xml no longer has the README's three lights";
        for (int k = 0; k < 3; ++k) scene.lights[k].intensity = colours[k];
        options.background = glm::vec3(0.0f);
    }

    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    const Image image = renderChecked(scene, options, &stats);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writeImage(image, artifactDir() + "/reference_" + caseName(r) + ".png");

    const Image refImage = readImage(dir + "/reference/" + r.image + ".png");
    ASSERT_EQ(refImage.width, kSize);
    ASSERT_EQ(refImage.height, kSize);
    Bytes ours = toBytes(image, false), ref = toBytes(refImage, true);
    ToleranceFn tolerance = [](int, int, int) { return double(kTolerance); };
    std::vector<bool> exclude;
    if (r.kind == Reference::BlockMeans) {
        constexpr int kBlock = 5;
        const BlockMeans a = blockMeans(ours, kBlock), b = blockMeans(ref, kBlock);
        ours = a.means;
        ref = b.means;
        tolerance = [a, b, w = ours.width](int x, int y, int c) {
            const std::size_t k = (static_cast<std::size_t>(y) * w + x) * 3 + c;
            return kTolerance + 3.0 * std::sqrt(a.varianceOfMean[k] + b.varianceOfMean[k]);
        };
        exclude = grazingGlossBlocks(scene, options, kBlock);
    }
    const Score s = score(ours, ref, tolerance, exclude);
    std::printf("[reference] %-32s %-38s %s %6d non-edge %s, %.4f within 2/255 (all: %.4f), %.2f s\n", r.image,
                r.scene, r.kind == Reference::BlockMeans ? "5x5 blocks" : "pixels    ", s.nonEdge,
                r.kind == Reference::BlockMeans ? "blocks" : "pixels", s.nonEdgeWithin, s.allWithin, seconds);
    if (s.excluded)
        std::printf("[reference] %-32s grazing glossy floor: %d blocks excluded, %.4f within, %.4f not brighter\n",
                    r.image, s.excluded, s.excludedWithin, s.excludedNotBrighter);
    EXPECT_GE(s.excludedNotBrighter, kRequired);
    EXPECT_GT(s.nonEdge, ref.width * ref.height / 4) << "the non-edge set is too small to mean anything";
    EXPECT_GE(s.nonEdgeWithin, kRequired) << r.image << ": see " << artifactDir() << "/reference_" << caseName(r) << ".png";
}

INSTANTIATE_TEST_SUITE_P(Upstream, ReferenceRender, ::testing::ValuesIn(kReferences),
                         [](const ::testing::TestParamInfo<Reference>& info) { return std::string(info.param.image); });
INSTANTIATE_TEST_SUITE_P(JsonTwins, ReferenceRender, ::testing::ValuesIn(kJsonTwinReferences),
                         [](const ::testing::TestParamInfo<Reference>& info) { return caseName(info.param); });

}  // namespace
}  // namespace vkrt::test
