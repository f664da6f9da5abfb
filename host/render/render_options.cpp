#include "render_options.h"

#include <stdexcept>

namespace vkrt {

std::string samplerName(SamplerKind sampler) {
    switch (sampler) {
    case SamplerKind::Jittered: return "jittered";
    case SamplerKind::Regular: return "regular";
    case SamplerKind::Random: return "random";
    case SamplerKind::Sobol: return "sobol";
    }
    return "unknown";
}

SamplerKind parseSampler(const std::string& name) {
    for (SamplerKind s : {SamplerKind::Jittered, SamplerKind::Regular, SamplerKind::Random, SamplerKind::Sobol})
        if (samplerName(s) == name) return s;
    throw std::invalid_argument("unknown sampler '" + name + "' (expected jittered, regular, random or sobol)");
}

}  // namespace vkrt
