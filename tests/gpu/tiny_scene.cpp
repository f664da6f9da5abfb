#include "tiny_scene.h"

namespace vkrt::test {

TinyScene::TinyScene() {
    scene.path = "tiny.xml";
    Camera camera;
    camera.position = glm::vec3(0.0f, 0.0f, 5.0f);
    camera.gaze = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.focalLength = 1.0f;
    camera.imagePlaneWidth = 0.5f;
    scene.cameras.push_back(camera);
    Light light;
    light.position = glm::vec3(2.0f, 4.0f, 3.0f);
    scene.lights.push_back(light);
    Shader shader;
    shader.name = "grey";
    shader.diffuse = glm::vec3(0.5f);
    scene.shaders.push_back(shader);
    Shape sphere;
    sphere.type = ShapeType::Sphere;
    sphere.center = glm::vec3(0.0f);
    sphere.radius = 1.0f;
    scene.shapes.push_back(sphere);

    bvh::SceneBvh& b = accel.bvh;
    const std::uint32_t minusMax = glm::floatBitsToUint(-3.402823466e38f), plusMax = glm::floatBitsToUint(3.402823466e38f);
    const std::uint32_t lo = glm::floatBitsToUint(-1.0f), hi = glm::floatBitsToUint(1.0f);
    bvh::BinaryNode node{};
    node.xy0 = glm::uvec4(lo, hi, lo, hi);
    node.xy1 = glm::uvec4(plusMax, minusMax, plusMax, minusMax);  // empty second child
    node.z01 = glm::uvec4(lo, hi, plusMax, minusMax);
    node.link = glm::uvec4(0u, bvh::NODE_NONE, 1u, 0u);  // child 0: leaf of primitive 0
    b.nodes = {node, node};                               // node 1: top level, leaf of instance 0
    gpu::Primitive prim{};
    prim.a = glm::uvec4(glm::floatBitsToUint(0.0f), glm::floatBitsToUint(0.0f), glm::floatBitsToUint(0.0f), gpu::PRIM_KIND_SPHERE);
    prim.b = glm::uvec4(glm::floatBitsToUint(1.0f), 0u, 0u, 0u);
    b.prims = {prim};
    b.primSource = {0};
    b.groups = {bvh::GroupRange{0, 0, 1, glm::vec3(-1.0f), glm::vec3(1.0f)}};
    gpu::Instance instance{};
    for (int r = 0; r < 3; ++r) {
        instance.worldToObject[r][r] = instance.objectToWorld[r][r] = instance.normalToWorld[r][r] = 1.0f;
    }
    instance.info = glm::uvec4(0u, gpu::MATERIAL_NONE, 0u, 0u);
    b.instances = {instance};
    b.topRoot = 1;
    accel.groupPrims = {{PrimOrigin{&scene.shapes[0], -1}}};
    accel.instanceOrigin = {-1};
    accel.instanceEmitter = {-1};
}

GpuSceneData TinyScene::gpu() const { return prepareGpuScene(scene, accel); }

RenderOptions smallRender(int width, int height, int samples) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.samplesPerPixel = samples;
    o.quiet = true;
    o.seed = 7;
    return o;
}

}  // namespace vkrt::test
