#include "invariance_scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scene_building.h"

namespace vkrt::stability {

Scene invarianceScene() {
    Scene scene;
    scene.path = "invariance (built in code)";
    scene.background = glm::vec3(0.1f, 0.12f, 0.2f);
    scene.cameras.push_back(perspective({0.0f, 2.4f, 6.5f}, {0.0f, 0.6f, 0.0f}, 1.0f, 1.0f));
    scene.lights.push_back(areaLight({0.8f, 7.0f, 2.0f}, {0.0f, -1.0f, 0.0f}, 1.0f, 1.0f, glm::vec3(0.6f)));
    scene.lights.push_back(pointLight({-4.0f, 6.0f, 5.0f}, glm::vec3(0.35f)));

    const int grey = add(scene, lambertian(glm::vec3(0.7f)));
    const int shiny = add(scene, glossy({0.6f, 0.25f, 0.1f}, 0.4f, 0.15f));
    const int glass = add(scene, dielectric(1.5f));
    const int blue = add(scene, blinnPhong({0.2f, 0.35f, 0.7f}, glm::vec3(0.3f), 16.0f));
    const int yellow = add(scene, lambertian({0.8f, 0.6f, 0.2f}));
    Shader jade = glossy({0.25f, 0.6f, 0.35f}, 0.3f, 0.0f);
    jade.type = ShaderType::Glaze;
    const int green = add(scene, jade);

    scene.shapes.push_back(box({-5.0f, -0.5f, -5.0f}, {5.0f, 0.0f, 5.0f}, grey));         // floor
    scene.shapes.push_back(sphere({-1.4f, 0.8f, 0.0f}, 0.8f, shiny));                     // resting on the floor
    scene.shapes.push_back(sphere({0.9f, 0.6f, 1.4f}, 0.6f, glass));
    scene.shapes.push_back(box({0.4f, 0.0f, -1.6f}, {1.6f, 1.0f, -0.6f}, blue));           // standing on the floor
    scene.shapes.push_back(box({0.3f, 0.0f, -1.85f}, {2.4f, 1.6f, -1.65f}, yellow));       // wall 0.05 behind the block
    scene.shapes.push_back(box({-3.0f, 0.05f, 1.0f}, {-2.0f, 0.05f, 2.0f}, blue));         // zero-thickness tile 0.05 above the floor
    scene.shapes.push_back(triangle({-3.0f, 0.0f, -1.6f}, {-1.2f, 0.0f, -2.6f}, {-2.3f, 1.9f, -2.3f}, yellow));

    const int ring = addMesh(scene, torus(0.55f, 0.2f, 32, 16));
    glm::mat4 lying = glm::translate(glm::mat4(1.0f), glm::vec3(2.3f, 0.2f, 0.3f));
    lying = glm::rotate(lying, glm::radians(30.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    addInstancedMesh(scene, ring, green, lying);
    glm::mat4 standing = glm::translate(glm::mat4(1.0f), glm::vec3(-0.2f, 0.75f, -0.7f));
    standing = glm::rotate(standing, glm::radians(75.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    addInstancedMesh(scene, ring, shiny, standing);
    // Non-uniform scale: the instance transform's condition number enters the GPU's float
    // world-to-object rounding.
    glm::mat4 flattened = glm::translate(glm::mat4(1.0f), glm::vec3(-2.6f, 0.08f, 2.2f));
    flattened = glm::scale(flattened, glm::vec3(1.2f, 0.4f, 0.8f));
    addInstancedMesh(scene, ring, blue, flattened);
    return scene;
}

}  // namespace vkrt::stability
