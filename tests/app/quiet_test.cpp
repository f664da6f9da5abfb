// -q means "no progress bar, summary or warnings" (the help's words): the render's radiance
// warnings (NaN/Inf samples, sums past float) are printed without it and not with it.
#include <gtest/gtest.h>

#include "render_steps.h"
#include "scene_builder.h"

namespace vkrt {
namespace {

// A wall of diffuse 0.5 under a light of 2e38: samples of 1e38 that sum past float at 4 rpp.
Scene overflowingWall() {
    Scene scene;
    scene.path = "overflowing wall (built in code)";
    scene.cameras.push_back(test::orthographicCamera({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}, 2.0f));
    scene.lights.push_back(test::pointLight({0.0f, 0.0f, 10.0f}, glm::vec3(2e38f, 1.0f, 1.0f)));
    const int wall = test::addShader(scene, test::makeShader(ShaderType::Lambertian, glm::vec3(0.5f)));
    scene.shapes.push_back(test::box({-3.0f, -3.0f, -1.0f}, {3.0f, 3.0f, 0.0f}, wall));
    return scene;
}

std::string warningsOf(bool quiet) {
    RenderOptions options;
    options.width = 8;
    options.height = 6;
    options.samplesPerPixel = 4;
    options.quiet = quiet;
    testing::internal::CaptureStderr();
    renderOnCpu(overflowingWall(), options);
    return testing::internal::GetCapturedStderr();
}

TEST(Quiet, SilencesTheRadianceWarningsThatARenderOtherwisePrints) {
    EXPECT_NE(warningsOf(false).find("48 pixel(s) summed their samples past float's range"), std::string::npos) << warningsOf(false);
    EXPECT_EQ(warningsOf(true), "");
}

}  // namespace
}  // namespace vkrt
