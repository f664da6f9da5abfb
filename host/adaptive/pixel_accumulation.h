// What an adaptive render has computed so far: per pixel, how many of its samples and their sums.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace vkrt::adaptive {

struct PixelAccumulation {
    int width = 0, height = 0;
    glm::ivec2 rows{0, 0};             // the rows rendered; the others keep count 0
    std::vector<std::uint32_t> count;  // samples [0, count) of each pixel have been added
    std::vector<glm::vec3> sum;        // all of them in sample order, in float: as a uniform render sums
    std::vector<glm::vec3> oddSum;     // the odd-numbered ones (sobol2's second sequence), in float

    PixelAccumulation() = default;
    PixelAccumulation(int w, int h, glm::ivec2 rowRange)
        : width(w), height(h), rows(rowRange), count(pixels(), 0u), sum(pixels(), glm::vec3(0.0f)),
          oddSum(pixels(), glm::vec3(0.0f)) {}
    std::size_t pixels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x; }
    // The pixel's mean radiance (black before its first sample).
    glm::vec3 mean(std::size_t p) const { return count[p] > 0 ? sum[p] / static_cast<float>(count[p]) : glm::vec3(0.0f); }
};

}  // namespace vkrt::adaptive
