// Plain mesh shapes that name one OBJ share one group, one tree (issue 38 item 4: 101 shapes naming
// a 100K-triangle mesh once took 101 trees and 2 GB). Each shape still shades with its own shader
// (its instance's override), and an image with the mesh named five times is the image with it
// named once, bit for bit (the copies coincide, and tie in the same shading).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cpu_renderer.h"
#include "diagnostics.h"
#include "scene_accel.h"
#include "scene_loader.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

std::string sceneNaming(int copies, bool ownShaders) {
    const std::string mesh = sourceDir() + "/scenes/meshes/torus.obj";
    std::string xml = "<scene bgColor=\"0.1 0.1 0.2\"><camera><position>0 1 4</position><lookatPoint>0 0 0</lookatPoint></camera>\n"
                      "<light type=\"point\"><position>2 4 3</position><intensity>1 1 1</intensity></light>\n";
    for (int k = 0; k < copies; ++k)
        xml += "<shader name=\"s" + std::to_string(k) + "\" type=\"Lambertian\"><diffuse>0." + std::to_string(k + 1) +
               " 0.5 0.5</diffuse></shader>\n";
    for (int k = 0; k < copies; ++k)
        xml += "<shape name=\"m" + std::to_string(k) + "\" type=\"mesh\"><file>" + mesh + "</file><shader ref=\"s" +
               std::to_string(ownShaders ? k : 0) + "\"/></shape>\n";
    return xml + "</scene>\n";
}

Scene load(const std::string& name, const std::string& text) {
    const std::string path = artifactDir() + "/" + name;
    std::ofstream(path) << text;
    Diagnostics diagnostics;
    return loadScene(path, LoadOptions{}, diagnostics);
}

TEST(MeshSharing, ShapesNamingOneMeshShareOneGroupAndKeepTheirShaders) {
    const Scene scene = load("mesh_sharing_five.xml", sceneNaming(5, true));
    ASSERT_EQ(scene.meshes.size(), 1u);
    const SceneAccel accel = prepareCpuScene(scene);
    EXPECT_EQ(accel.bvh.groups.size(), 2u);  // the loose shapes' group, and the torus once
    ASSERT_EQ(accel.bvh.instances.size(), 6u);
    const bvh::GroupRange& torus = accel.bvh.groups[1];
    for (std::uint32_t i = 1; i <= 5; ++i) {
        EXPECT_EQ(gpu::instanceGroup(accel.bvh.instances[i].info), 1u);
        EXPECT_EQ(accel.shaderOf(i, torus.firstPrim), static_cast<int>(i - 1)) << "instance " << i;
    }
}

TEST(MeshSharing, FiveCopiesRenderAsOne) {
    const Scene one = load("mesh_sharing_one.xml", sceneNaming(1, false));
    const Scene five = load("mesh_sharing_same.xml", sceneNaming(5, false));
    RenderOptions options;
    options.width = 48;
    options.height = 36;
    options.samplesPerPixel = 4;
    const Image a = renderCpu(one, prepareCpuScene(one), options);
    const Image b = renderCpu(five, prepareCpuScene(five), options);
    EXPECT_EQ(a.pixels, b.pixels);
    double sum = 0.0;
    for (const glm::vec3& p : a.pixels) sum += p.x;
    EXPECT_GT(sum, 0.05 * a.pixels.size());  // the torus is in view and lit, not an empty frame
}

}  // namespace
}  // namespace vkrt::test
