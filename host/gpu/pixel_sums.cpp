#include "pixel_sums.h"

namespace vkrt {

Image resolve(const std::vector<glm::vec4>& sums, int width, int height, int samples) {
    Image image(width, height);
    const auto n = static_cast<float>(samples);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = glm::vec3(sums[i]) / n;
    return image;
}

Image resolveSoFar(const std::vector<glm::vec4>& sums, int width, int height, const std::vector<TileRect>& tiles,
                   std::size_t current, int currentSamples, int samples, int firstRow) {
    Image image(width, height);
    for (std::size_t t = 0; t <= current && t < tiles.size(); ++t) {
        const auto n = static_cast<float>(t < current ? samples : currentSamples);
        const TileRect& r = tiles[t];
        for (std::uint32_t y = r.y; y < r.y + r.height; ++y)
            for (std::uint32_t x = r.x; x < r.x + r.width; ++x) {
                const std::size_t i = static_cast<std::size_t>(y + firstRow) * width + x;
                image.pixels[i] = glm::vec3(sums[i]) / n;
            }
    }
    return image;
}

}  // namespace vkrt
