// The host-side tables (device_host.h layouts) built from the scene model, and FrameParams.
#include <cmath>

#include <gtest/gtest.h>

#include "frame_params.h"
#include "sampling.h"
#include "scene_tables.h"
#include "tiny_scene.h"

namespace vkrt {
namespace {

TEST(SceneTables, MaterialCarriesEveryParameter) {
    Shader s;
    s.type = ShaderType::BlinnPhongMirrored;
    s.diffuse = {0.1f, 0.2f, 0.3f};
    s.specular = {0.4f, 0.5f, 0.6f};
    s.phongExp = 32.0f;
    s.mirrorCoef = 0.25f;
    s.roughness = 0.125f;
    s.refractiveIndex = 1.5f;
    s.attenuation = {0.9f, 0.8f, 0.7f};
    s.diffuseTexture = 2;
    const gpu::Material m = toGpuMaterial(s);
    EXPECT_EQ(m.diffuse, glm::vec4(0.1f, 0.2f, 0.3f, 0.0f));
    EXPECT_EQ(m.specular, glm::vec4(0.4f, 0.5f, 0.6f, 32.0f));
    EXPECT_EQ(m.attenuation, glm::vec4(0.9f, 0.8f, 0.7f, 1.5f));
    EXPECT_EQ(m.params.x, 0.25f);
    EXPECT_EQ(m.params.y, 0.125f);
    EXPECT_EQ(m.ids, glm::uvec4(gpu::SHADER_BLINN_PHONG_MIRRORED, 2u, gpu::TEXTURE_NONE, 0u));
}

TEST(SceneTables, ShaderTypeIds) {
    const std::pair<ShaderType, std::uint32_t> types[] = {
        {ShaderType::Lambertian, gpu::SHADER_LAMBERTIAN}, {ShaderType::BlinnPhong, gpu::SHADER_BLINN_PHONG},
        {ShaderType::Mirror, gpu::SHADER_MIRROR},         {ShaderType::Glaze, gpu::SHADER_GLAZE},
        {ShaderType::BlinnPhongMirrored, gpu::SHADER_BLINN_PHONG_MIRRORED},
        {ShaderType::Dielectric, gpu::SHADER_DIELECTRIC}, {ShaderType::CoolToWarm, gpu::SHADER_COOL_TO_WARM}};
    for (const auto& [type, id] : types) {
        Shader s;
        s.type = type;
        EXPECT_EQ(toGpuMaterial(s).ids.x, id);
    }
}

// RENDERING.md §4's worked example: a downward light has width along +x and length along +z.
TEST(SceneTables, AreaLightFrameOfTheSpec) {
    glm::vec3 t, b;
    areaLightFrame({0.0f, -1.0f, 0.0f}, t, b);
    EXPECT_EQ(t, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(b, glm::vec3(0.0f, 0.0f, 1.0f));
    areaLightFrame({0.0f, 0.0f, 1.0f}, t, b);  // |n.z| > 0.9: a = x
    EXPECT_EQ(t, glm::vec3(0.0f, -1.0f, 0.0f));
    EXPECT_EQ(b, glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::vec3 n = glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f));
    areaLightFrame(n, t, b);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(b), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(t, n), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(b, n), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(t, b), 0.0f, 1e-6f);
}

TEST(SceneTables, LightsEdgesAndAreaOrdinals) {
    test::TinyScene tiny;
    Scene& scene = tiny.scene;
    Light area;
    area.type = LightType::Area;
    area.position = {1.0f, 5.0f, 2.0f};
    area.intensity = {3.0f, 2.0f, 1.0f};
    area.normal = {0.0f, -1.0f, 0.0f};
    area.width = 2.0f;
    area.length = 0.5f;
    scene.lights = {scene.lights[0], area, scene.lights[0], area};
    const SceneTables t = buildSceneTables(scene, tiny.accel);
    ASSERT_EQ(t.lights.size(), 4u);
    EXPECT_EQ(t.lights[0].info, glm::uvec4(gpu::LIGHT_POINT, 0u, 0u, 0u));
    EXPECT_EQ(t.lights[0].edgeU, glm::vec4(0.0f));
    EXPECT_EQ(t.lights[1].info, glm::uvec4(gpu::LIGHT_AREA, 0u, 0u, 0u));
    EXPECT_EQ(t.lights[3].info, glm::uvec4(gpu::LIGHT_AREA, 1u, 0u, 0u));  // second area light
    EXPECT_EQ(glm::vec3(t.lights[1].position), area.position);
    EXPECT_EQ(glm::vec3(t.lights[1].intensity), area.intensity);
    EXPECT_EQ(t.lights[1].edgeU, glm::vec4(2.0f, 0.0f, 0.0f, 0.0f));
    EXPECT_EQ(t.lights[1].edgeV, glm::vec4(0.0f, 0.0f, 0.5f, 0.0f));
}

// A loose triangle (group 0) and a two-triangle mesh (group 1) whose primitives the "builder"
// reordered: primInfo must follow primSource back to each triangle's own corners.
TEST(SceneTables, PrimInfoFollowsPrimSourceToMeshCorners) {
    Scene scene;
    scene.shaders.resize(3);
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    mesh.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 0.25f}};
    mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
    Mesh other;  // a second mesh first in the list, to shift the attribute base
    other.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    other.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    other.triangles = {{0, 1, 2}};
    scene.meshes = {other, mesh};
    Shape loose;
    loose.type = ShapeType::Triangle;
    loose.shader = 2;
    Shape meshShape;
    meshShape.type = ShapeType::Mesh;
    meshShape.mesh = 1;
    meshShape.shader = 1;
    scene.shapes = {loose, meshShape};

    SceneAccel accel;
    accel.groupPrims = {{PrimOrigin{&scene.shapes[0], -1}}, {PrimOrigin{&scene.shapes[1], 0}, PrimOrigin{&scene.shapes[1], 1}}};
    accel.bvh.prims.resize(3);
    accel.bvh.primSource = {0, 1, 0};  // flat prim 1 = mesh triangle 1, flat prim 2 = mesh triangle 0
    accel.bvh.groups = {bvh::GroupRange{0, 0, 1, {}, {}}, bvh::GroupRange{0, 1, 2, {}, {}}};

    const SceneTables t = buildSceneTables(scene, accel);
    ASSERT_EQ(t.primInfos.size(), 3u);
    EXPECT_EQ(t.primInfos[0].data, glm::uvec4(2u, gpu::ATTRIB_NONE, gpu::ATTRIB_NONE, gpu::ATTRIB_NONE));
    EXPECT_EQ(t.primInfos[1].data, glm::uvec4(1u, 3u + 1u, 3u + 3u, 3u + 2u));  // base 3: after `other`
    EXPECT_EQ(t.primInfos[2].data, glm::uvec4(1u, 3u + 0u, 3u + 1u, 3u + 2u));
    ASSERT_EQ(t.vertexAttribs.size(), 7u);
    EXPECT_EQ(t.vertexAttribs[3 + 3].normalU, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(t.vertexAttribs[3 + 3].vPad.x, 0.25f);
    EXPECT_EQ(t.vertexAttribs[0].vPad.x, 0.0f);  // no uvs: zero

    scene.meshes[1].normals.pop_back();
    EXPECT_THROW(buildSceneTables(scene, accel), std::runtime_error);
}

TEST(SceneTables, TexturesArePackedBackToBack) {
    test::TinyScene tiny;
    Texture a;
    a.width = 2;
    a.height = 1;
    a.rgba8 = {0x11223344u, 0x55667788u};
    Texture b;
    b.width = 1;
    b.height = 3;
    b.rgba8 = {1u, 2u, 3u};
    tiny.scene.textures = {a, b};
    const SceneTables t = buildSceneTables(tiny.scene, tiny.accel);
    ASSERT_EQ(t.textures.size(), 2u);
    EXPECT_EQ(t.textures[0].info, glm::uvec4(0u, 2u, 1u, 0u));
    EXPECT_EQ(t.textures[1].info, glm::uvec4(2u, 1u, 3u, 0u));
    EXPECT_EQ(t.texels, (std::vector<std::uint32_t>{0x11223344u, 0x55667788u, 1u, 2u, 3u}));
}

TEST(FrameParams, CameraBasisOfTheSpec) {
    CameraBasis b = cameraBasis({0.0f, 0.0f, -3.0f});
    EXPECT_EQ(b.w, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(b.u, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(b.v, glm::vec3(0.0f, 1.0f, 0.0f));
    b = cameraBasis({0.0f, -2.0f, 0.0f});  // straight down: up = (1, 0, 0), world +x at the top
    EXPECT_EQ(b.w, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(b.u, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(b.v, glm::vec3(1.0f, 0.0f, 0.0f));
    b = cameraBasis({1.0f, 0.3f, -2.0f});
    EXPECT_NEAR(glm::dot(b.u, b.v), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(b.u, b.w), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(b.v), 1.0f, 1e-6f);
    EXPECT_NEAR(b.u.y, 0.0f, 1e-6f);  // u stays horizontal
}

TEST(FrameParams, CarriesOptionsAndGrids) {
    test::TinyScene tiny;
    tiny.scene.background = {0.1f, 0.2f, 0.3f};
    tiny.scene.cameras[0].type = CameraType::Orthographic;
    RenderOptions o = test::smallRender(200, 100, 16);
    o.lightSamples = 3;
    o.glossSamples = 2;
    o.maxDepth = 5;
    o.seed = 42;
    o.sampler = SamplerKind::Regular;
    gpu::FrameParams f = makeFrameParams(tiny.scene, tiny.accel, o);
    EXPECT_EQ(f.cameraU.w, 0.5f);
    EXPECT_EQ(f.cameraV.w, 0.25f);  // H = W * ny / nx
    EXPECT_EQ(f.cameraW.w, 1.0f);
    EXPECT_EQ(glm::vec3(f.cameraPosition), glm::vec3(0.0f, 0.0f, 5.0f));
    EXPECT_EQ(f.image, glm::uvec4(200u, 100u, gpu::CAMERA_ORTHOGRAPHIC, 0u));
    EXPECT_EQ(f.sampling, glm::uvec4(gpu::SAMPLER_REGULAR, 16u, 3u, 2u));
    EXPECT_EQ(f.scene, glm::uvec4(42u, 5u, 1u, tiny.accel.bvh.topRoot));
    EXPECT_EQ(glm::vec3(f.background), tiny.scene.background);
    EXPECT_EQ(f.pixelGrid, sampling::makeSampleGrid(16));
    EXPECT_EQ(f.lightGrid, sampling::makeSampleGrid(48));
    EXPECT_EQ(f.glossGrid, sampling::makeSampleGrid(32));
    o.background = glm::vec3(1.0f, 0.0f, 1.0f);
    f = makeFrameParams(tiny.scene, tiny.accel, o);
    EXPECT_EQ(glm::vec3(f.background), glm::vec3(1.0f, 0.0f, 1.0f));
}

// The kernel takes its basis from the frame constants (shaders/camera.glsl), so the camera's own up
// vector reaches the GPU only through makeFrameParams.
TEST(FrameParams, CarryTheCamerasUpVector) {
    test::TinyScene tiny;
    tiny.scene.cameras[0].gaze = glm::vec3(0.0f, -1.0f, 0.0f);
    const RenderOptions o = test::smallRender(8, 8, 1);
    gpu::FrameParams f = makeFrameParams(tiny.scene, tiny.accel, o);
    EXPECT_EQ(glm::vec3(f.cameraU), glm::vec3(0.0f, 0.0f, 1.0f));  // no up: the rule, +x at the top
    EXPECT_EQ(glm::vec3(f.cameraV), glm::vec3(1.0f, 0.0f, 0.0f));
    tiny.scene.cameras[0].up = glm::vec3(0.0f, 0.0f, -3.0f);
    f = makeFrameParams(tiny.scene, tiny.accel, o);
    EXPECT_EQ(glm::vec3(f.cameraU), glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(glm::vec3(f.cameraV), glm::vec3(0.0f, 0.0f, -1.0f));
    EXPECT_EQ(glm::vec3(f.cameraW), glm::vec3(0.0f, 1.0f, 0.0f));
}

// FrameParams::image.w carries host/lighting/final_rays.h's answer, each flag in its own bit.
TEST(FrameParams, SayWhichRaysAtTheMaximumDepthCannotBringLight) {
    test::TinyScene tiny;
    RenderOptions o = test::smallRender(8, 8, 1);
    const auto finalBits = [&] {
        return makeFrameParams(tiny.scene, tiny.accel, o).image.w & (gpu::FINAL_BOUNCE_DARK | gpu::FINAL_REFLECTION_DARK);
    };
    EXPECT_EQ(finalBits(), 0u);  // its Lambertian is lit at every depth
    tiny.scene.shaders[0].diffuseBounce = true;  // Diffuse: black at the maximum depth
    tiny.scene.background = glm::vec3(0.0f);
    EXPECT_EQ(finalBits(), gpu::FINAL_BOUNCE_DARK | gpu::FINAL_REFLECTION_DARK);
    tiny.scene.emitters.emplace_back();
    o.estimator = Estimator::Nee;  // light samples alone find the emitter; mirror rays see it
    EXPECT_EQ(finalBits(), gpu::FINAL_BOUNCE_DARK);
    o.estimator = Estimator::MisPower;
    EXPECT_EQ(finalBits(), 0u);
}

// RENDERING.md §6: glass continues one branch exactly where a rendered surface is Diffuse (the
// bit the kernel reads, and the CPU's pathTraced, from one function).
TEST(FrameParams, SayThatGlassContinuesOneBranchWhereASurfaceIsDiffuse) {
    test::TinyScene tiny;
    const RenderOptions o = test::smallRender(8, 8, 1);
    EXPECT_EQ(makeFrameParams(tiny.scene, tiny.accel, o).image.w & gpu::PATH_DIELECTRIC_ONE_BRANCH, 0u);
    tiny.scene.shaders.push_back(tiny.scene.shaders[0]);
    tiny.scene.shaders.back().diffuseBounce = true;  // a Diffuse shader no shape uses: still Whitted
    EXPECT_EQ(makeFrameParams(tiny.scene, tiny.accel, o).image.w & gpu::PATH_DIELECTRIC_ONE_BRANCH, 0u);
    tiny.scene.shaders[0].diffuseBounce = true;
    EXPECT_EQ(makeFrameParams(tiny.scene, tiny.accel, o).image.w & gpu::PATH_DIELECTRIC_ONE_BRANCH,
              gpu::PATH_DIELECTRIC_ONE_BRANCH);
}

TEST(FrameParams, RefusesOptionsTheKernelCannotHonour) {
    test::TinyScene tiny;
    auto bad = [&](auto change) {
        RenderOptions o = test::smallRender(8, 8, 1);
        change(o);
        EXPECT_THROW(makeFrameParams(tiny.scene, tiny.accel, o), std::invalid_argument);
    };
    bad([](RenderOptions& o) { o.width = 0; });
    bad([](RenderOptions& o) { o.samplesPerPixel = 0; });
    bad([](RenderOptions& o) { o.lightSamples = 0; });
    bad([](RenderOptions& o) { o.glossSamples = 0; });
    bad([](RenderOptions& o) { o.maxDepth = -1; });
    bad([](RenderOptions& o) { o.camera = 1; });
}

}  // namespace
}  // namespace vkrt
