#include "shader_emitters.h"

#include <utility>
#include <vector>

namespace vkrt::rules {

namespace {

glm::vec3 emissionOf(const Scene& scene, int shader) {
    return shader >= 0 && shader < static_cast<int>(scene.shaders.size()) ? scene.shaders[static_cast<std::size_t>(shader)].emission
                                                                         : glm::vec3(0.0f);
}

}  // namespace

void makeShaderEmitters(Scene& scene, Diagnostics& diagnostics) {
    const int lightsBefore = static_cast<int>(scene.lights.size());
    // Placed after the file's lights, as a shape light listed last would be.
    const auto emitterOf = [&](const std::string& name, glm::vec3 radiance, const SourceLocation& where) {
        Emitter emitter;
        emitter.name = name;
        emitter.radiance = radiance;
        emitter.where = where;
        emitter.lightsBefore = lightsBefore;
        return emitter;
    };
    std::vector<Shape> shapes;
    for (Shape& shape : scene.shapes) {
        const glm::vec3 emission = emissionOf(scene, shape.shader);
        if (emission == glm::vec3(0.0f)) {
            shapes.push_back(std::move(shape));
            continue;
        }
        Emitter emitter = emitterOf(shape.name, emission, shape.where);
        emitter.shape = std::move(shape);
        scene.emitters.push_back(std::move(emitter));
    }
    scene.shapes = std::move(shapes);

    std::vector<Instance> instances;
    for (Instance& instance : scene.instances) {
        const int shader = instance.shaderOverride >= 0 ? instance.shaderOverride
                                                        : scene.prototypes[static_cast<std::size_t>(instance.prototype)].shader;
        const glm::vec3 emission = emissionOf(scene, shader);
        if (emission == glm::vec3(0.0f)) {
            instances.push_back(std::move(instance));
            continue;
        }
        if (instance.moving) {
            diagnostics.warn({instance.where.file, instance.where.line, "instance",
                              "a moving instance with an Emitter shader is drawn as its black surface: emitters do not move",
                              instance.name, instance.where.column});
            instances.push_back(std::move(instance));
            continue;
        }
        Emitter emitter = emitterOf(instance.name, emission, instance.where);
        emitter.prototype = instance.prototype;
        emitter.shape.name = instance.name;
        emitter.shape.shader = shader;
        emitter.steps = std::move(instance.steps);
        emitter.objectToWorld = instance.objectToWorld;
        scene.emitters.push_back(std::move(emitter));
    }
    scene.instances = std::move(instances);
}

}  // namespace vkrt::rules
