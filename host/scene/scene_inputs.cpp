#include "scene_inputs.h"

namespace vkrt {

std::vector<SceneInput> sceneInputs(const Scene& scene) {
    std::vector<SceneInput> files{{scene.path, "the scene file"}};
    for (const Mesh& mesh : scene.meshes) files.push_back({mesh.path, "a mesh"});
    for (const Texture& texture : scene.textures) files.push_back({texture.path, "a texture"});
    if (!scene.envMapPrefix.empty())
        for (const char* face : {"posX", "negX", "posY", "negY", "posZ", "negZ"})
            files.push_back({scene.envMapPrefix + face + ".png", "an environment map face"});
    if (!scene.envMapVertCross.empty()) files.push_back({scene.envMapVertCross, "an environment map"});
    return files;
}

}  // namespace vkrt
