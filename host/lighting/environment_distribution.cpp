#include "environment_distribution.h"

#include <algorithm>
#include <stdexcept>

#include "environment_sampling.h"

namespace vkrt {

namespace {

double luminance(std::uint32_t t) {
    return (0.2126 * double(t & 0xffu) + 0.7152 * double((t >> 8) & 0xffu) + 0.0722 * double((t >> 16) & 0xffu)) / 255.0;
}

// The CDF of `weights` (all > 0) into table[first .. first + n], in double, stored as floats with
// the last entry exactly 1. Throws if float rounding made a step 0 (the floors are meant to
// prevent it; a zero step would be a cell sampling never picks).
void storeCdf(const std::vector<double>& weights, std::vector<float>& table, std::size_t first) {
    double total = 0.0;
    for (double w : weights) total += w;
    double sum = 0.0;
    table[first] = 0.0f;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        sum += weights[i];
        table[first + i + 1] = i + 1 == weights.size() ? 1.0f : static_cast<float>(sum / total);
        if (!(table[first + i + 1] > table[first + i]))
            throw std::logic_error("environment distribution: a cell's probability rounds to 0");
    }
}

}  // namespace

EnvironmentDistribution environmentDistribution(const EnvironmentTexels& environment) {
    EnvironmentDistribution out;
    const std::uint32_t n = environment.faceSize;
    if (n == 0) return out;
    const std::uint32_t c = std::min(n, kMaxEnvironmentCells);
    out.cells = c;
    const std::size_t row = n + 2u;

    // Raw weights: solid angle x mean luminance of the bordered texels the lookup reads in the cell.
    // Cell [s0, s1) reads bordered texels floor(s0 N + 0.5) .. floor(s1 N + 0.5) (cube_map.h,
    // cubeTexelFootprint: texel x's centre is at s = (x - 0.5) / N, and a lookup reads x and x + 1).
    const std::size_t rows = 6u * c;
    std::vector<double> weight(rows * c);
    double totalWeight = 0.0;
    auto span = [&](std::uint32_t cell) {
        const std::uint32_t lo = static_cast<std::uint32_t>(double(cell) * n / c + 0.5);
        const std::uint32_t hi = std::min<std::uint32_t>(static_cast<std::uint32_t>(double(cell + 1) * n / c + 0.5) + 1u, n + 1u);
        return glm::uvec2(lo, hi);
    };
    for (std::uint32_t face = 0; face < 6; ++face) {
        const std::uint32_t* texels = environment.texels.data() + face * row * row;
        for (std::uint32_t cy = 0; cy < c; ++cy) {
            const glm::uvec2 ys = span(cy);
            for (std::uint32_t cx = 0; cx < c; ++cx) {
                const glm::uvec2 xs = span(cx);
                double sum = 0.0;
                for (std::uint32_t y = ys.x; y <= ys.y; ++y)
                    for (std::uint32_t x = xs.x; x <= xs.y; ++x) sum += luminance(texels[y * row + x]);
                const double mean = sum / double((ys.y - ys.x + 1) * (xs.y - xs.x + 1));
                const float solidAngle = envsampling::cubeFaceRectSolidAngle(glm::vec2(float(cx), float(cy)) / float(c),
                                                                              glm::vec2(float(cx + 1), float(cy + 1)) / float(c));
                const double w = mean * double(solidAngle);
                weight[(face * c + cy) * c + cx] = w;
                totalWeight += w;
            }
        }
    }
    // The floors (environment_distribution.h says why). A black map: weights by solid angle alone.
    const double meanWeight = totalWeight / double(weight.size());
    for (std::uint32_t r = 0; r < rows; ++r) {
        for (std::uint32_t cx = 0; cx < c; ++cx) {
            double& w = weight[r * c + cx];
            if (meanWeight > 0.0) {
                w += 1e-3 * meanWeight;
            } else {
                const std::uint32_t cy = r % c;
                w = envsampling::cubeFaceRectSolidAngle(glm::vec2(float(cx), float(cy)) / float(c),
                                                        glm::vec2(float(cx + 1), float(cy + 1)) / float(c));
            }
        }
    }
    out.table.assign(envsampling::envTableSize(c), 0.0f);
    std::vector<double> rowWeights(rows);
    std::vector<double> cellsOfRow(c);
    for (std::uint32_t r = 0; r < rows; ++r) {
        double rowSum = 0.0;
        for (std::uint32_t cx = 0; cx < c; ++cx) rowSum += weight[r * c + cx];
        const double rowFloor = 1e-3 * rowSum / double(c);
        for (std::uint32_t cx = 0; cx < c; ++cx) cellsOfRow[cx] = weight[r * c + cx] + rowFloor;
        rowWeights[r] = rowSum + rowFloor * double(c);
        storeCdf(cellsOfRow, out.table, envsampling::envRowCdf(c, r));
    }
    storeCdf(rowWeights, out.table, 0);
    return out;
}

EnvironmentSample sampleEnvironment(const EnvironmentDistribution& distribution, glm::vec2 u) {
    const glm::vec4 s = envsampling::sampleEnvironment(distribution.table.data(), distribution.cells, u);
    return {glm::vec3(s), s.w};
}

float environmentPdf(const EnvironmentDistribution& distribution, glm::vec3 dir) {
    return envsampling::environmentPdf(distribution.table.data(), distribution.cells, dir);
}

}  // namespace vkrt
