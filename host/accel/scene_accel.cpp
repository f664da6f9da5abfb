#include "scene_accel.h"

#include <map>
#include <utility>

namespace vkrt {

namespace {

using bvh::PrimitiveInput;

PrimitiveInput primitiveOf(const Shape& shape) {
    PrimitiveInput p;
    switch (shape.type) {
    case ShapeType::Sphere:
        p.kind = gpu::PRIM_KIND_SPHERE;
        p.a = shape.center;
        p.b = glm::vec3(shape.radius, 0.0f, 0.0f);
        break;
    case ShapeType::Box:
        p.kind = gpu::PRIM_KIND_BOX;
        p.a = shape.minPt;
        p.b = shape.maxPt;
        break;
    case ShapeType::Triangle:
        p.kind = gpu::PRIM_KIND_TRIANGLE;
        p.a = shape.v0;
        p.b = shape.v1;
        p.c = shape.v2;
        break;
    case ShapeType::Mesh:
        break;  // expanded by the caller
    }
    return p;
}

// Appends a shape's primitives (one, or every triangle of its mesh) to a group.
void addShape(const Scene& scene, const Shape& shape, std::vector<PrimitiveInput>& prims,
              std::vector<PrimOrigin>& origins) {
    if (shape.type != ShapeType::Mesh) {
        prims.push_back(primitiveOf(shape));
        origins.push_back({&shape, -1});
        return;
    }
    const Mesh& mesh = scene.meshes[shape.mesh];
    prims.reserve(prims.size() + mesh.triangles.size());
    origins.reserve(origins.size() + mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        PrimitiveInput p;
        p.kind = gpu::PRIM_KIND_TRIANGLE;
        p.a = mesh.positions[tri.x];
        p.b = mesh.positions[tri.y];
        p.c = mesh.positions[tri.z];
        prims.push_back(p);
        origins.push_back({&shape, static_cast<int>(t)});
    }
}

}  // namespace

SceneAccel buildSceneAccel(const Scene& scene, const bvh::BuildOptions& options) {
    SceneAccel accel;
    std::vector<std::vector<PrimitiveInput>> groups;
    std::vector<bvh::InstanceInput> instances;

    // Group 0: loose spheres, boxes and triangles in world space.
    groups.emplace_back();
    accel.groupPrims.emplace_back();
    for (const Shape& shape : scene.shapes)
        if (shape.type != ShapeType::Mesh) addShape(scene, shape, groups[0], accel.groupPrims[0]);
    instances.push_back({0, glm::mat4(1.0f), gpu::MATERIAL_NONE});
    accel.instanceOrigin.push_back(-1);

    // Mesh shapes placed directly in the scene: one group (one copy of the triangles, one tree)
    // per mesh, however many shapes name it, as instances share a prototype's. A shape whose
    // shader differs from the group's first shape says so through its instance's override: 101
    // shapes naming one 100K-triangle OBJ cost one tree, not 101 (issue 38).
    std::map<int, std::pair<std::uint32_t, int>> meshGroups;  // mesh -> (group, the first shape's shader)
    for (const Shape& shape : scene.shapes) {
        if (shape.type != ShapeType::Mesh) continue;
        auto [found, first] = meshGroups.try_emplace(shape.mesh, static_cast<std::uint32_t>(groups.size()), shape.shader);
        if (first) {
            groups.emplace_back();
            accel.groupPrims.emplace_back();
            addShape(scene, shape, groups.back(), accel.groupPrims.back());
        }
        const auto [group, groupShader] = found->second;
        const std::uint32_t override =
            shape.shader == groupShader || shape.shader < 0 ? gpu::MATERIAL_NONE : static_cast<std::uint32_t>(shape.shader);
        instances.push_back({group, glm::mat4(1.0f), override});
        accel.instanceOrigin.push_back(-1);
    }

    // Prototypes, placed by the scene's instances.
    const auto firstPrototypeGroup = static_cast<std::uint32_t>(groups.size());
    for (const Shape& prototype : scene.prototypes) {
        groups.emplace_back();
        accel.groupPrims.emplace_back();
        addShape(scene, prototype, groups.back(), accel.groupPrims.back());
    }
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        const std::uint32_t override =
            inst.shaderOverride >= 0 ? static_cast<std::uint32_t>(inst.shaderOverride) : gpu::MATERIAL_NONE;
        // An end pose equal to the start is no motion: the instance renders as a static one, bit
        // for bit (docs/RENDERING.md §9).
        const bool moving = inst.moving && inst.objectToWorldEnd != inst.objectToWorld;
        instances.push_back({firstPrototypeGroup + static_cast<std::uint32_t>(inst.prototype), inst.objectToWorld, override,
                             moving, inst.objectToWorldEnd});
        accel.instanceOrigin.push_back(static_cast<int>(i));
    }

    // Shape emitters: visible geometry whose material is the emitter's (emitterMaterial), so a
    // ray that meets one knows which emitter it saw. They never move (docs/RENDERING.md §9).
    for (std::size_t e = 0; e < scene.emitters.size(); ++e) {
        const Emitter& emitter = scene.emitters[e];
        std::uint32_t group = 0;
        if (emitter.prototype >= 0) {
            group = firstPrototypeGroup + static_cast<std::uint32_t>(emitter.prototype);
        } else {
            group = static_cast<std::uint32_t>(groups.size());
            groups.emplace_back();
            accel.groupPrims.emplace_back();
            addShape(scene, emitter.shape, groups.back(), accel.groupPrims.back());
        }
        instances.push_back({group, emitter.objectToWorld, emitterMaterial(scene, e)});
        accel.instanceOrigin.push_back(-1);
    }
    accel.instanceEmitter.assign(instances.size(), -1);
    for (std::size_t e = 0; e < scene.emitters.size(); ++e)
        accel.instanceEmitter[instances.size() - scene.emitters.size() + e] = static_cast<int>(e);

    accel.bvh = bvh::buildSceneBvh(groups, instances, options);
    accel.lighting = std::make_shared<const SceneLighting>(buildSceneLighting(scene));
    return accel;
}

}  // namespace vkrt
