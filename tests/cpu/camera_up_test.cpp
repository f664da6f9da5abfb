// Which way up a camera looking straight down (or up) shows the world (docs/RENDERING.md §1,
// issue 39): the course's up (0,1,0) is parallel to such a gaze, and the rule shows world +x at the
// top of the image, as the 2022 course renders of StanfordBunny.json do; a camera's own up vector
// (vkrt's addition) turns the image. A red marker sphere at +x on a grey floor, seen from above:
// each test finds the side of the image the marker lands on.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "analytic_scene.h"
#include "camera.h"
#include "camera_basis.h"

namespace vkrt::test {
namespace {

// The floor and the marker face the camera: `side` +1 puts the camera above them looking down,
// -1 below them looking up (a ceiling).
Scene markerAtPlusX(float side = 1.0f) {
    Scene scene;
    scene.cameras.push_back(perspectiveCamera({0.0f, 5.0f * side, 0.0f}, {0.0f, -side, 0.0f}));
    scene.lights.push_back(pointLight({0.0f, 10.0f * side, 0.0f}, glm::vec3(1.0f)));
    const int grey = addShader(scene, makeShader(ShaderType::Lambertian, glm::vec3(0.5f)));
    const int red = addShader(scene, makeShader(ShaderType::Lambertian, {1.0f, 0.0f, 0.0f}));
    scene.shapes.push_back(side > 0.0f ? box({-3, -1, -3}, {3, 0, 3}, grey) : box({-3, 0, -3}, {3, 1, 3}, grey));
    scene.shapes.push_back(sphere({1.2f, 0.3f * side, 0.0f}, 0.4f, red));
    return scene;
}

// "top", "bottom", "left" or "right": where the red pixels lie, seen from the image's centre.
std::string markerSide(const Image& image) {
    double x = 0.0, y = 0.0;
    int count = 0;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const glm::vec3 c = image.at(i, j);
            if (c.r > 0.2f && c.g < 0.05f) {
                x += i + 0.5 - image.width / 2.0;
                y += j + 0.5 - image.height / 2.0;
                ++count;
            }
        }
    if (count == 0) return "nowhere";
    if (std::abs(y) >= std::abs(x)) return y < 0.0 ? "top" : "bottom";  // row 0 is the top
    return x < 0.0 ? "left" : "right";
}

std::string renderedSide(const Scene& scene) {
    RenderOptions o;
    o.width = 32;
    o.height = 32;
    return markerSide(renderChecked(scene, o));
}

TEST(StraightDownCamera, BasisPutsWorldPlusXAtTheTop) {
    for (const float side : {1.0f, -1.0f}) {  // looking down, looking up
        SCOPED_TRACE(side > 0.0f ? "looking down" : "looking up");
        const cpu::CameraFrame f = cpu::makeCameraFrame(markerAtPlusX(side).cameras[0], 32, 32);
        EXPECT_EQ(f.v, glm::vec3(1.0f, 0.0f, 0.0f));  // image up
        EXPECT_EQ(f.u, glm::vec3(0.0f, 0.0f, side));  // image right: +z from above, -z from below
        EXPECT_EQ(f.w, glm::vec3(0.0f, side, 0.0f));
    }
}

TEST(StraightDownCamera, ShowsWorldPlusXAtTheTopOfTheImage) {
    EXPECT_EQ(renderedSide(markerAtPlusX(1.0f)), "top");
    EXPECT_EQ(renderedSide(markerAtPlusX(-1.0f)), "top");
}

TEST(StraightDownCamera, TurnsWithTheCamerasUpVector) {
    const struct {
        glm::vec3 up;
        const char* side;
    } cases[] = {
        {{0.0f, 0.0f, -1.0f}, "right"},  // vkrt before issue 39: +x to the right, -z up
        {{0.0f, 0.0f, 1.0f}, "left"},
        {{-2.0f, 0.0f, 0.0f}, "bottom"},  // any length
        {{1.0f, 0.5f, 0.0f}, "top"},      // not perpendicular to the gaze: its projection is up
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(::testing::Message() << "up " << c.up.x << "," << c.up.y << "," << c.up.z);
        Scene scene = markerAtPlusX();
        scene.cameras[0].up = c.up;
        EXPECT_EQ(renderedSide(scene), c.side);
    }
}

// The rule changes nothing but straight up and down: an up vector equal to what the rule picks
// renders the same bits, and a gaze just inside the threshold still uses (0,1,0).
TEST(StraightDownCamera, AGivenUpEqualToTheRulesRendersTheSameBits) {
    RenderOptions o;
    o.width = 24;
    o.height = 24;
    Scene down = markerAtPlusX();
    const Image byRule = renderChecked(down, o);
    down.cameras[0].up = glm::vec3(1.0f, 0.0f, 0.0f);
    EXPECT_EQ(renderChecked(down, o).pixels, byRule.pixels);

    Scene tilted = markerAtPlusX();
    tilted.cameras[0].gaze = glm::vec3(0.0f, -1.0f, 0.02f);  // |g.y| = 0.9998: not vertical
    EXPECT_EQ(courseUp(tilted.cameras[0].gaze), glm::vec3(0.0f, 1.0f, 0.0f));
    const Image tiltedByRule = renderChecked(tilted, o);
    tilted.cameras[0].up = glm::vec3(0.0f, 1.0f, 0.0f);
    EXPECT_EQ(renderChecked(tilted, o).pixels, tiltedByRule.pixels);
}

TEST(StraightDownCamera, UpVectorsThatCannotOrientTheCameraAreNamed) {
    const glm::vec3 down(0.0f, -1.0f, 0.0f);
    EXPECT_EQ(upProblem(glm::vec3(0.0f), down), "up vector has zero length");
    EXPECT_EQ(upProblem(glm::vec3(0.0f, INFINITY, 0.0f), down), "up vector must be finite");
    EXPECT_EQ(upProblem(glm::vec3(NAN, 1.0f, 0.0f), down), "up vector must be finite");
    EXPECT_NE(upProblem(glm::vec3(0.0f, 3.0f, 0.0f), down).find("parallel to the view direction"), std::string::npos);
    EXPECT_NE(upProblem(glm::vec3(0.0f, -1e-30f, 1e-34f), down).find("parallel"), std::string::npos);  // tiny, still parallel
    EXPECT_EQ(upProblem(glm::vec3(1e-30f, 0.0f, 0.0f), down), "");  // any length that has a direction
    EXPECT_EQ(upProblem(glm::vec3(0.0f, 1.0f, 0.02f), down), "");   // 1.1 degrees off: usable
}

}  // namespace
}  // namespace vkrt::test
