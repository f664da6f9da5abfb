// The scene's geometry as bvh_builder sees it: geometry groups and instances, and the way back
// from a hit (instance, flat primitive) to the scene model, for shading. Both renderers use it.
//
// Groups: group 0 holds the loose spheres, boxes and triangles of Scene::shapes (world space,
// placed by one identity instance); every mesh that shapes of Scene::shapes name is one group, each
// such shape an identity instance of it (its shader as the instance's override where it differs
// from the group's first shape's); every prototype is a group placed by the scene's instances. Shape emitters
// (Scene::emitters) follow: a prototype's group placed by the emitter's transform, or a group of
// the emitter's own shape; their material override is emitterMaterial(e), past every shader.
#pragma once

#include <cstdint>
#include <vector>

#include <memory>

#include "bvh.h"
#include "scene_lighting.h"
#include "scene.h"

namespace vkrt {

// Where a group's input primitive came from.
struct PrimOrigin {
    const Shape* shape = nullptr;  // the loose shape, mesh shape or prototype
    int triangle = -1;             // mesh triangle index, or -1
};

struct SceneAccel {
    bvh::SceneBvh bvh;
    std::vector<std::vector<PrimOrigin>> groupPrims;  // per group, per input primitive
    std::vector<int> instanceOrigin;                  // per BVH instance: index into Scene::instances, or -1
    std::vector<int> instanceEmitter;                 // per BVH instance: index into Scene::emitters, or -1
    // What the renderers sample emitters and the environment by, built with the tree (shared:
    // copies of a prepared scene share it). Null in hand-made accels: renderers then build it.
    std::shared_ptr<const SceneLighting> lighting;

    // The primitive a hit refers to.
    const PrimOrigin& origin(std::uint32_t instance, std::uint32_t flatPrim) const {
        const std::uint32_t group = gpu::instanceGroup(bvh.instances[instance].info);
        return groupPrims[group][bvh.primSource[flatPrim]];
    }
    // The emitter a hit is on, or -1.
    int emitterOf(std::uint32_t instance) const { return instanceEmitter[instance]; }
    // The shader index a hit shades with: the instance's override, else the shape's own (not for
    // an emitter's hit: its override is emitterMaterial(), past Scene::shaders).
    int shaderOf(std::uint32_t instance, std::uint32_t flatPrim) const {
        const std::uint32_t override = gpu::instanceMaterialOverride(bvh.instances[instance].info);
        return override != gpu::MATERIAL_NONE ? static_cast<int>(override) : origin(instance, flatPrim).shape->shader;
    }
};

// The material index of emitter e in the renderers' material tables: after the scene's shaders.
inline std::uint32_t emitterMaterial(const Scene& scene, std::size_t e) {
    return static_cast<std::uint32_t>(scene.shaders.size() + e);
}

// The scene must outlive the result (PrimOrigin points into it).
SceneAccel buildSceneAccel(const Scene& scene, const bvh::BuildOptions& options = {});

}  // namespace vkrt
