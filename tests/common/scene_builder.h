// Scenes built in code for every test suite: one small constructor per part of the scene model,
// so each test states its whole scene where it is used.
#pragma once

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt::test {

Camera perspectiveCamera(glm::vec3 position, glm::vec3 gaze, float focalLength = 1.0f, float planeWidth = 1.0f);
Camera orthographicCamera(glm::vec3 position, glm::vec3 gaze, float planeWidth);
Light pointLight(glm::vec3 position, glm::vec3 intensity);
// normal need not be unit length (it is normalised here, as the loader does).
Light areaLight(glm::vec3 centre, glm::vec3 normal, float width, float length, glm::vec3 intensity);
Shader makeShader(ShaderType type, glm::vec3 diffuse = glm::vec3(0.0f));
Shape sphere(glm::vec3 centre, float radius, int shader);
Shape box(glm::vec3 lo, glm::vec3 hi, int shader);
Shape triangle(glm::vec3 v0, glm::vec3 v1, glm::vec3 v2, int shader);

// Each returns the index of the added element.
int addShader(Scene& scene, const Shader& shader);
int addMesh(Scene& scene, Mesh mesh);

}  // namespace vkrt::test
