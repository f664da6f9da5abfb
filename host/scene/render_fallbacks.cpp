#include "render_fallbacks.h"

namespace vkrt {

const char* fallbackProblem(Fallback fallback) {
    switch (fallback) {
        case Fallback::EmitterShader: return "Emitter shaders rendered as black Lambertian (their emission is not rendered)";
    }
    return "";
}

}  // namespace vkrt
