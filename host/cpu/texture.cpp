#include "texture.h"

#include <cmath>

namespace vkrt::cpu {

namespace {

glm::vec3 texel(const Texture& t, int x, int y) {
    const std::uint32_t c = t.rgba8[static_cast<std::size_t>(y) * t.width + x];
    return glm::vec3(static_cast<float>(c & 0xffu), static_cast<float>((c >> 8) & 0xffu),
                     static_cast<float>((c >> 16) & 0xffu)) * (1.0f / 255.0f);
}

int wrap(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}

}  // namespace

glm::vec3 sampleTexture(const Texture& t, glm::vec2 uv) {
    if (t.width <= 0 || t.height <= 0 || t.rgba8.empty()) return glm::vec3(1.0f);
    // Reduce to [0,1) first so the integer texel indices below cannot overflow for far-off uvs.
    const float u = uv.x - std::floor(uv.x);
    const float v = uv.y - std::floor(uv.y);
    const float x = u * static_cast<float>(t.width) - 0.5f;
    const float y = (1.0f - v) * static_cast<float>(t.height) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    const int xa = wrap(ix, t.width), xb = wrap(ix + 1, t.width);
    const int ya = wrap(iy, t.height), yb = wrap(iy + 1, t.height);
    const glm::vec3 top = (1.0f - fx) * texel(t, xa, ya) + fx * texel(t, xb, ya);
    const glm::vec3 bottom = (1.0f - fx) * texel(t, xa, yb) + fx * texel(t, xb, yb);
    return (1.0f - fy) * top + fy * bottom;
}

}  // namespace vkrt::cpu
