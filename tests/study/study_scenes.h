// Scenes for the sampler studies' tests, each with a value computed independently of the renderers:
//  - an edge pixel: a 1x1 image whose pixel a triangle edge crosses diagonally, black triangle over
//    a coloured background, so the pixel is exactly background x (area above the edge);
//  - a penumbra pixel: a 1x1 image of a ground point half in the shadow of a half-plane occluder
//    under a square area light, whose radiance is an integral over the light done in double here.
// And the repository's example scenes, loaded.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "scene.h"

namespace vkrt::test {

struct PixelScene {
    Scene scene;
    glm::dvec3 expected{0.0};  // the pixel's exact value
};

PixelScene edgePixelScene();
PixelScene penumbraPixelScene();

// scenes/<name>.xml of the repository, its camera settled as the CLI would.
Scene exampleScene(const std::string& name);

}  // namespace vkrt::test
