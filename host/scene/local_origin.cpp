#include "local_origin.h"

#include <cmath>
#include <limits>
#include <map>

#include <glm/gtc/matrix_transform.hpp>

#include "scene_rules.h"

namespace vkrt::rules {

std::optional<glm::vec3> localPosition(const glm::dvec3& exact, const glm::dvec3& origin) {
    const glm::dvec3 local = exact - origin;
    for (int c = 0; c < 3; ++c)
        if (!(std::abs(local[c]) <= std::numeric_limits<float>::max())) return std::nullopt;
    return glm::vec3(local);
}

glm::mat4 placeRelativeTo(const std::vector<TransformStep>& steps, const std::vector<glm::dvec3>& exactTranslations,
                          const glm::dvec3& origin) {
    glm::dmat4 m(1.0);
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const TransformStep& step = steps[i];
        glm::dmat4 s(1.0);
        switch (step.kind) {
            case TransformKind::Translate: s[3] = glm::dvec4(exactTranslations.at(i), 1.0); break;
            case TransformKind::Scale: s = glm::scale(glm::dmat4(1.0), glm::dvec3(step.amount)); break;
            case TransformKind::Rotate: s = glm::dmat4(axisRotation(step.axis, static_cast<double>(step.amount.x))); break;
        }
        m = m * s;
    }
    m[3] -= glm::dvec4(origin, 0.0);  // T(-origin) * M: only the translation column moves
    return glm::mat4(m);
}

void rebaseWorldMeshes(Scene& scene) {
    if (scene.origin == glm::dvec3(0.0)) return;
    std::map<int, int> rebased;  // object-space mesh -> its world-space copy
    const auto worldCopy = [&](int mesh) {
        if (const auto found = rebased.find(mesh); found != rebased.end()) return found->second;
        Mesh copy = scene.meshes[static_cast<std::size_t>(mesh)];
        for (glm::vec3& p : copy.positions) p = glm::vec3(glm::dvec3(p) - scene.origin);
        const int index = static_cast<int>(scene.meshes.size());
        scene.meshes.push_back(std::move(copy));
        rebased[mesh] = index;
        return index;
    };
    for (Shape& shape : scene.shapes)
        if (shape.type == ShapeType::Mesh) shape.mesh = worldCopy(shape.mesh);
    for (Emitter& emitter : scene.emitters)
        if (emitter.prototype < 0 && emitter.steps.empty() && emitter.shape.type == ShapeType::Mesh)
            emitter.shape.mesh = worldCopy(emitter.shape.mesh);
}

}  // namespace vkrt::rules
