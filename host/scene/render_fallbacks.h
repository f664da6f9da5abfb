// JSON-era features the renderers cannot show yet (path-traced Diffuse, Emitter shaders, shape
// lights: issue 20), what they show instead, and the warning that says so. Each
// loader warns once per scene, at the first thing that needs a fallback, with these texts. This
// is the one place to change when the renderers learn the real thing (and the loaders' calls of
// FallbackNotes, which then go).
#pragma once

#include <array>
#include <utility>

#include "scene.h"

namespace vkrt {

enum class Fallback { Diffuse, EmitterShader, ShapeLight };

// The warning's problem text, naming the fallback.
const char* fallbackProblem(Fallback fallback);

// Remembers which fallbacks a load has warned about, so each is warned once per scene.
class FallbackNotes {
public:
    bool first(Fallback fallback) { return !std::exchange(seen_[static_cast<std::size_t>(fallback)], true); }

private:
    std::array<bool, 3> seen_{};
};

// The point light that stands in for scene.emitters[index] (Light::emitterStandIn): at the
// centre of the emitter's world-space bounds, with intensity = its radiance. The course's lights
// have no falloff and no emitter cosine (docs/RENDERING.md §4), so this is the limit of the shape
// shrunk to a point. The emitting shape itself is not drawn: it would shadow its own stand-in.
Light emitterStandInLight(const Scene& scene, int index);

}  // namespace vkrt
