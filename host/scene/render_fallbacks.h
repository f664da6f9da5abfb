// JSON-era features the renderers do not show as the file means them, what they show instead,
// and the warning that says so: today only the `Emitter` shader (J26; no course file uses one),
// rendered as black Lambertian. Each loader warns once per scene, at the first thing that needs
// a fallback.
#pragma once

#include <array>
#include <utility>

#include "scene.h"

namespace vkrt {

enum class Fallback { EmitterShader };

// The warning's problem text, naming the fallback.
const char* fallbackProblem(Fallback fallback);

// Remembers which fallbacks a load has warned about, so each is warned once per scene.
class FallbackNotes {
public:
    bool first(Fallback fallback) { return !std::exchange(seen_[static_cast<std::size_t>(fallback)], true); }

private:
    std::array<bool, 1> seen_{};
};


}  // namespace vkrt
