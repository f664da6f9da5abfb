#include "scene_transform.h"

#include <cmath>
#include <set>

namespace vkrt::stability {

namespace {

glm::vec3 point(const Similarity& t, glm::vec3 p) { return glm::vec3(t.scale * glm::dvec3(p) + t.translation); }
float length(const Similarity& t, float l) { return static_cast<float>(t.scale * l); }

}  // namespace

std::ostream& operator<<(std::ostream& os, const Placement& p) { return os << p.name; }

glm::dvec3 away(double distance) { return {distance, 0.5 * distance, -distance}; }

glm::dmat4 matrixOf(const Similarity& t) {
    glm::dmat4 m(t.scale);
    m[3] = glm::dvec4(t.translation, 1.0);
    return m;
}

Scene transformed(const Scene& scene, const Similarity& t) {
    Scene out = scene;
    for (Camera& c : out.cameras) {
        c.position = point(t, c.position);
        c.gaze = glm::vec3(t.scale * glm::dvec3(c.gaze));  // lookatPoint - position, scaled
        c.focalLength = length(t, c.focalLength);
        c.imagePlaneWidth = length(t, c.imagePlaneWidth);
    }
    for (Light& l : out.lights) {
        l.position = point(t, l.position);
        l.width = length(t, l.width);
        l.length = length(t, l.length);
    }
    for (Shader& s : out.shaders)
        for (int c = 0; c < 3; ++c)
            s.attenuation[c] = static_cast<float>(std::pow(double(s.attenuation[c]), 1.0 / t.scale));
    for (Shape& s : out.shapes) {
        s.center = point(t, s.center);
        s.radius = length(t, s.radius);
        s.minPt = point(t, s.minPt);
        s.maxPt = point(t, s.maxPt);
        s.v0 = point(t, s.v0);
        s.v1 = point(t, s.v1);
        s.v2 = point(t, s.v2);
    }
    // Loose mesh shapes are in world space; prototypes' meshes stay in object space.
    std::set<int> looseMeshes;
    for (const Shape& s : scene.shapes)
        if (s.type == ShapeType::Mesh) looseMeshes.insert(s.mesh);
    for (int mesh : looseMeshes)
        for (glm::vec3& p : out.meshes[mesh].positions) p = point(t, p);
    const glm::dmat4 m = matrixOf(t);
    for (Instance& i : out.instances) i.objectToWorld = glm::mat4(m * glm::dmat4(i.objectToWorld));
    return out;
}

}  // namespace vkrt::stability
