#include "render_options.h"

#include <algorithm>
#include <cmath>

#include <stdexcept>

namespace vkrt {

std::string samplerName(SamplerKind sampler) {
    switch (sampler) {
    case SamplerKind::Jittered: return "jittered";
    case SamplerKind::Regular: return "regular";
    case SamplerKind::Random: return "random";
    case SamplerKind::Sobol: return "sobol";
    case SamplerKind::Sobol2: return "sobol2";
    }
    return "unknown";
}

SamplerKind parseSampler(const std::string& name) {
    for (SamplerKind s : {SamplerKind::Jittered, SamplerKind::Regular, SamplerKind::Random, SamplerKind::Sobol, SamplerKind::Sobol2})
        if (samplerName(s) == name) return s;
    throw std::invalid_argument("unknown sampler '" + name + "' (expected jittered, regular, random, sobol or sobol2)");
}

std::string estimatorName(Estimator estimator) {
    switch (estimator) {
    case Estimator::Bounce: return "bounce";
    case Estimator::Nee: return "nee";
    case Estimator::MisBalance: return "mis-balance";
    case Estimator::MisPower: return "mis";
    }
    return "unknown";
}

Estimator parseEstimator(const std::string& name) {
    for (Estimator e : {Estimator::Bounce, Estimator::Nee, Estimator::MisBalance, Estimator::MisPower})
        if (estimatorName(e) == name) return e;
    throw std::invalid_argument("unknown estimator '" + name + "' (expected bounce, nee, mis-balance or mis)");
}

glm::vec2 shutterOf(const RenderOptions& options) {
    const glm::vec2 shutter = options.shutter.value_or(glm::vec2(0.0f, 1.0f));
    const auto text = [&] { return std::to_string(shutter.x) + "," + std::to_string(shutter.y); };
    if (!std::isfinite(shutter.x) || !std::isfinite(shutter.y))
        throw std::invalid_argument("shutter " + text() + ": open and close must be finite");
    if (shutter.y < shutter.x) throw std::invalid_argument("shutter " + text() + ": it closes before it opens");
    return shutter;
}

glm::ivec2 rowsOf(const RenderOptions& options) {
    const glm::ivec2 rows = options.rows.value_or(glm::ivec2(0, options.height));
    if (rows.x < 0 || rows.y > options.height || rows.x >= rows.y)
        throw std::invalid_argument("rows " + std::to_string(rows.x) + ".." + std::to_string(rows.y) + " are not a part of the " +
                                    std::to_string(options.height) + "-row image");
    return rows;
}

std::vector<int> checkpointEnds(int units, int checkpoints) {
    std::vector<int> ends;
    const int n = std::max(checkpoints, 1);
    for (int p = 1; p <= n; ++p) {
        const auto end = static_cast<int>(static_cast<long long>(units) * p / n);
        if (end > 0 && (ends.empty() || end > ends.back())) ends.push_back(end);
    }
    return ends;
}

glm::ivec2 partRows(int height, int part, int parts) {
    const auto edge = [&](int k) { return static_cast<int>(static_cast<long long>(height) * k / parts); };
    return {edge(part - 1), edge(part)};
}

void applyReferenceLook(RenderOptions& options) {
    options.background = glm::vec3(kReferenceLookBackground);
    options.environment = false;
}

}  // namespace vkrt
