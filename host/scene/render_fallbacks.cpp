#include "render_fallbacks.h"

#include <algorithm>

namespace vkrt {

namespace {

// The centre of a shape's bounds in its own space.
glm::vec3 boundsCentre(const Scene& scene, const Shape& shape) {
    switch (shape.type) {
        case ShapeType::Sphere: return shape.center;
        case ShapeType::Box: return 0.5f * (shape.minPt + shape.maxPt);
        case ShapeType::Triangle: return 0.5f * (glm::min(shape.v0, glm::min(shape.v1, shape.v2)) + glm::max(shape.v0, glm::max(shape.v1, shape.v2)));
        case ShapeType::Mesh: {
            const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(shape.mesh));
            glm::vec3 lo(mesh.positions.at(0)), hi(lo);
            for (const glm::vec3& p : mesh.positions) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            return 0.5f * (lo + hi);
        }
    }
    return glm::vec3(0.0f);
}

}  // namespace

const char* fallbackProblem(Fallback fallback) {
    switch (fallback) {
        case Fallback::EmitterShader: return "Emitter shaders rendered as black Lambertian (their emission is not rendered)";
    }
    return "";
}

Light emitterStandInLight(const Scene& scene, int index) {
    const Emitter& emitter = scene.emitters.at(static_cast<std::size_t>(index));
    const Shape& shape = emitter.prototype >= 0 ? scene.prototypes.at(static_cast<std::size_t>(emitter.prototype)) : emitter.shape;
    // An affine map takes the centre of a box to the centre of its image's bounds (the image is
    // a parallelepiped, symmetric about that point).
    Light light;
    light.type = LightType::Point;
    light.position = glm::vec3(emitter.objectToWorld * glm::vec4(boundsCentre(scene, shape), 1.0f));
    light.intensity = emitter.radiance;
    light.emitterStandIn = index;
    light.where = emitter.where;
    return light;
}

}  // namespace vkrt
