// Everything the renderers sample a scene's shape emitters and environment map by, built once per
// prepared scene (with its tree: SceneAccel::lighting) rather than once per render: the bordered
// reef faces and their distribution take ~0.14 s, a mesh emitter's triangle table ~0.1 s.
#pragma once

#include "emitter_table.h"
#include "environment_distribution.h"
#include "environment_map.h"
#include "scene.h"

namespace vkrt {

struct SceneLighting {
    EmitterTable emitters;                       // the shape emitters' records (emitter_table.h)
    EnvironmentTexels environment;               // the map's bordered faces (faceSize 0: none)
    EnvironmentDistribution environmentLights;   // its luminance distribution, for light samples
};

SceneLighting buildSceneLighting(const Scene& scene);

}  // namespace vkrt
