// The scene model turned into the arrays the kernel reads (device_host.h): materials, lights,
// per-primitive shading info, mesh vertex attributes and textures. Pure host code, no Vulkan.
#pragma once

#include <cstdint>
#include <vector>

#include "device_host.h"
#include <memory>

#include "scene_lighting.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt {

struct SceneTables {
    std::vector<gpu::Material> materials;        // one per Scene::shaders, same order, then one per
                                                 // Scene::emitters (emitterMaterial, scene_accel.h)
    std::vector<gpu::Light> lights;              // one per Scene::lights but shape lights, same order
    // The emitter records and the environment's faces and distribution, as they are uploaded:
    // the prepared scene's (SceneAccel::lighting), shared, not copied (the reef faces are 25 MB).
    std::shared_ptr<const SceneLighting> lighting = std::make_shared<const SceneLighting>();
    std::vector<gpu::PrimInfo> primInfos;        // parallel to SceneAccel::bvh.prims
    std::vector<gpu::VertexAttrib> vertexAttribs;// every mesh's vertices, mesh after mesh
    std::vector<gpu::TextureInfo> textures;      // one per Scene::textures
    std::vector<std::uint32_t> texels;           // all textures' RGBA8 texels, texture after texture
};

SceneTables buildSceneTables(const Scene& scene, const SceneAccel& accel);

gpu::Material toGpuMaterial(const Shader& shader);
// areaOrdinal: the light's position among the scene's area lights (its sampling dimension).
gpu::Light toGpuLight(const Light& light, std::uint32_t areaOrdinal);

// The area-light frame of docs/RENDERING.md §4: T = normalize(cross(a, n)) with a = z, or x when
// |n.z| > 0.9; B = cross(n, T).
void areaLightFrame(const glm::vec3& normal, glm::vec3& tangent, glm::vec3& bitangent);

}  // namespace vkrt
