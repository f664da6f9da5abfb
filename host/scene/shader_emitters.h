// The JSON `Emitter` shader (J26: `{"_type": "Emitter", "emission": c}`; no course file uses one)
// in the form renders use: every shape, and every still instance, whose shader is an Emitter with
// a non-black emission becomes a shape emitter (Scene::emitters) of radiance `emission`, exactly
// as if the file had given it as `{"_type": "shape", "intensity": emission, "shape": ...}`
// (docs/RENDERING.md §4). Both renderers then draw it and light the scene with it. A moving
// instance cannot be an emitter (emitters never move): it stays, drawn as the Emitter shader's
// black surface, with a warning. The loader applies this under LoadOptions::shaderEmitters;
// without it (vkrt convert, the loader's tests) the model keeps the file's form.
#pragma once

#include "diagnostics.h"
#include "scene.h"

namespace vkrt::rules {

void makeShaderEmitters(Scene& scene, Diagnostics& diagnostics);

}  // namespace vkrt::rules
