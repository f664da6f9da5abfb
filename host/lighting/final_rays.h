// Which rays that end at the maximum depth can still bring light, so that the renderers trace no
// ray whose answer is known to be black (docs/RENDERING.md §5 "Rays that cannot bring light").
// A hit of depth max-depth reflects nothing on a Diffuse, Mirror or Dielectric surface; such a
// ray adds light only by leaving the scene (background or environment map), by reaching a shape
// emitter, or by hitting a shader with local shading (Lambertian, Blinn-Phong, Glaze,
// BlinnPhongMirrored, CoolToWarm), which is lit at every depth. Skipping the others changes no
// pixel: the image is the same bit for bit, and only rays that add exactly 0 are not traced.
#pragma once

#include "render_options.h"
#include "scene.h"

namespace vkrt {

struct FinalRays {
    bool bounceSeesLight = true;      // a Diffuse bounce that ends at max-depth can bring light
    bool reflectionSeesLight = true;  // a mirror, gloss or dielectric ray that ends there can
};

// `options` gives the estimator (under nee a bounce that reaches an emitter or the environment
// adds nothing: light samples counted it), the background override and whether the map is used.
FinalRays finalRays(const Scene& scene, const RenderOptions& options);

}  // namespace vkrt
