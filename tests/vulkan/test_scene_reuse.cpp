// A prepared scene is uploaded once (GpuRenderer keeps its buffers: scene_upload.h): renders that
// follow, at other sizes, sample counts and seeds, must give the bytes a renderer that uploads
// afresh gives, and a second prepared scene must replace the first.
#include <gtest/gtest.h>

#include "vulkan_test_support.h"

namespace vkrt {
namespace {

using test::TinyScene;
using test::VulkanTest;

Image freshRender(const GpuSceneData& data, const RenderOptions& options) {
    GpuRenderer fresh({.validation = true});
    const Image image = fresh.render(data, options);
    EXPECT_EQ(fresh.validationLog()->count(), 0u) << fresh.validationLog()->joined();
    return image;
}

TEST_F(VulkanTest, RendersOfOnePreparedSceneReuseItsUploadAndKeepTheirBytes) {
    TinyScene tiny;
    const GpuSceneData data = tiny.gpu();
    GpuRenderer& gpu = renderer();
    RenderOptions small = test::smallRender(16, 12, 2);
    RenderOptions large = test::smallRender(40, 30, 3);  // more pixels: the sums' buffer grows
    large.seed = 7;

    GpuRenderStats first, second;
    const Image a = gpu.render(data, small, &first);
    const Image b = gpu.render(data, large, &second);
    const Image c = gpu.render(data, small);  // back to fewer pixels: the grown buffer is zeroed and reused
    EXPECT_TRUE(first.sceneUploaded);
    EXPECT_FALSE(second.sceneUploaded);
    EXPECT_GT(second.sceneBytes, first.sceneBytes);  // only the accumulation buffer grew

    EXPECT_EQ(a.pixels, freshRender(data, small).pixels);
    EXPECT_EQ(b.pixels, freshRender(data, large).pixels);
    EXPECT_EQ(c.pixels, a.pixels);

    // Another prepared scene (a second sphere colour): its own upload, its own image.
    TinyScene other;
    other.scene.shaders[0].diffuse = glm::vec3(0.1f, 0.9f, 0.2f);
    const GpuSceneData otherData = other.gpu();
    ASSERT_NE(otherData.uploadKey, data.uploadKey);
    GpuRenderStats third;
    const Image d = gpu.render(otherData, small, &third);
    EXPECT_TRUE(third.sceneUploaded);
    EXPECT_EQ(d.pixels, freshRender(otherData, small).pixels);
    EXPECT_NE(d.pixels, a.pixels);
    EXPECT_EQ(gpu.render(data, small).pixels, a.pixels);  // and the first again
}

}  // namespace
}  // namespace vkrt
