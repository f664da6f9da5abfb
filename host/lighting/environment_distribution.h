// The environment map's luminance distribution, for importance sampling it (docs/RENDERING.md
// §10.4): the tables shaders/shared/environment_sampling.h samples and evaluates, on both devices
// (the GPU reads `table` as float bits, an R32UI texel buffer, through VKRT_ENV_CDF; `cells` is
// the functions' `cells` argument).
//
// The grid has C x C cells per face, C = min(N, 64) (64: 24,576 cells, a 100 KB table; a cell of a
// 1024-texel face is 16 x 16 texels). A cell's weight is its solid angle times the mean
// luminance (Rec. 709: 0.2126 R + 0.7152 G + 0.0722 B, on byte / 255) of every texel the bilinear
// lookup reads inside the cell (its own and the ring half a texel around it), so a cell where the
// lookup is non-zero never has weight 0. Two floors follow, 1e-3 of the mean cell weight, then
// 1e-3 of the mean cell weight of the cell's row: every direction keeps pdf > 0, and no cell's
// step in its row's CDF is below float's resolution (without the second floor a cell 4e-8 of a
// row holding the sun would round to a zero step: a direction the lookup lights but sampling never
// picks, i.e. a biased estimate). An all-black map gets weights proportional to solid angle.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "environment_map.h"

namespace vkrt {

struct EnvironmentDistribution {
    std::uint32_t cells = 0;   // C; 0: no environment map (table empty)
    std::vector<float> table;  // envTableSize(C) floats: the marginal CDF, then each row's
};

inline constexpr std::uint32_t kMaxEnvironmentCells = 64;

EnvironmentDistribution environmentDistribution(const EnvironmentTexels& environment);

// sampleEnvironment / environmentPdf of shaders/shared/environment_sampling.h over `distribution`
// (cells > 0): a unit direction with its pdf per steradian, from u in [0, 1)^2; the pdf of a
// direction (any length but zero).
struct EnvironmentSample {
    glm::vec3 direction{0.0f};
    float pdf = 0.0f;
};
EnvironmentSample sampleEnvironment(const EnvironmentDistribution& distribution, glm::vec2 u);
float environmentPdf(const EnvironmentDistribution& distribution, glm::vec3 dir);

}  // namespace vkrt
