// A tiny scene for the GPU side's tests, with its acceleration structure made by hand (no BVH
// builder involved), and the options of small renders.
#pragma once

#include "kernel_inputs.h"
#include "render_options.h"
#include "scene.h"
#include "scene_accel.h"

namespace vkrt::test {

// A scene with one camera, one sphere, one point light and one Lambertian shader, and its
// acceleration structure built by hand (one bottom-level node, one identity instance, one
// top-level node). Not movable: the accel points into the scene.
struct TinyScene {
    Scene scene;
    SceneAccel accel;
    TinyScene();
    // Prepared for the GPU renderer from this scene and hand-made accel, as they are now.
    GpuSceneData gpu() const;
    TinyScene(const TinyScene&) = delete;
    TinyScene& operator=(const TinyScene&) = delete;
};

RenderOptions smallRender(int width, int height, int samples);

}  // namespace vkrt::test
