#include "scene_builder.h"

#include <utility>

namespace vkrt::test {

Camera perspectiveCamera(glm::vec3 position, glm::vec3 gaze, float focalLength, float planeWidth) {
    Camera c;
    c.type = CameraType::Perspective;
    c.position = position;
    c.gaze = gaze;
    c.focalLength = focalLength;
    c.imagePlaneWidth = planeWidth;
    return c;
}

Camera orthographicCamera(glm::vec3 position, glm::vec3 gaze, float planeWidth) {
    Camera c = perspectiveCamera(position, gaze, 1.0f, planeWidth);
    c.type = CameraType::Orthographic;
    return c;
}

Light pointLight(glm::vec3 position, glm::vec3 intensity) {
    Light l;
    l.type = LightType::Point;
    l.position = position;
    l.intensity = intensity;
    return l;
}

Light areaLight(glm::vec3 centre, glm::vec3 normal, float width, float length, glm::vec3 intensity) {
    Light l;
    l.type = LightType::Area;
    l.position = centre;
    l.normal = glm::normalize(normal);
    l.width = width;
    l.length = length;
    l.intensity = intensity;
    return l;
}

Shader makeShader(ShaderType type, glm::vec3 diffuse) {
    Shader s;
    s.type = type;
    s.diffuse = diffuse;
    return s;
}

Shape sphere(glm::vec3 centre, float radius, int shader) {
    Shape s;
    s.type = ShapeType::Sphere;
    s.center = centre;
    s.radius = radius;
    s.shader = shader;
    return s;
}

Shape box(glm::vec3 lo, glm::vec3 hi, int shader) {
    Shape s;
    s.type = ShapeType::Box;
    s.minPt = lo;
    s.maxPt = hi;
    s.shader = shader;
    return s;
}

Shape triangle(glm::vec3 v0, glm::vec3 v1, glm::vec3 v2, int shader) {
    Shape s;
    s.type = ShapeType::Triangle;
    s.v0 = v0;
    s.v1 = v1;
    s.v2 = v2;
    s.shader = shader;
    return s;
}

int addShader(Scene& scene, const Shader& shader) {
    scene.shaders.push_back(shader);
    return static_cast<int>(scene.shaders.size()) - 1;
}

int addMesh(Scene& scene, Mesh mesh) {
    scene.meshes.push_back(std::move(mesh));
    return static_cast<int>(scene.meshes.size()) - 1;
}

}  // namespace vkrt::test
