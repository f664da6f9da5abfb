#include "environment_map.h"

#include <cmath>

#include "cube_map.h"

namespace vkrt {

namespace {

std::uint32_t meanTexel(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t mean = 0;
    for (int shift = 0; shift < 32; shift += 8) {
        const std::uint32_t sum = ((a >> shift) & 0xffu) + ((b >> shift) & 0xffu) + ((c >> shift) & 0xffu);
        mean |= ((sum + 1u) / 3u) << shift;  // rounded to the nearest byte
    }
    return mean;
}

}  // namespace

glm::vec3 texelRadiance(std::uint32_t t) {
    return glm::vec3(float(t & 0xffu), float((t >> 8) & 0xffu), float((t >> 16) & 0xffu)) * (1.0f / 255.0f);
}

EnvironmentTexels borderedEnvironment(const Environment& environment) {
    EnvironmentTexels out;
    if (environment.faceSize <= 0) return out;
    const std::uint32_t n = static_cast<std::uint32_t>(environment.faceSize);
    const std::size_t row = n + 2u;
    const std::size_t faceTexels = row * row;
    out.faceSize = n;
    out.texels.assign(6 * faceTexels, 0u);
    auto own = [&](std::uint32_t face, std::uint32_t x, std::uint32_t y) {
        return environment.faces[face][static_cast<std::size_t>(y) * n + x];
    };
    for (std::uint32_t face = 0; face < 6; ++face) {
        std::uint32_t* bordered = out.texels.data() + face * faceTexels;
        for (std::uint32_t y = 0; y < n; ++y)
            for (std::uint32_t x = 0; x < n; ++x) bordered[(y + 1) * row + x + 1] = own(face, x, y);
        const int last = static_cast<int>(n) + 1;
        for (int i = 1; i < last; ++i) {
            for (const glm::ivec2 at : {glm::ivec2(0, i), glm::ivec2(last, i), glm::ivec2(i, 0), glm::ivec2(i, last)}) {
                const glm::uvec3 source = cubemap::cubeBorderSource(face, at.x, at.y, n);
                bordered[static_cast<std::size_t>(at.y) * row + static_cast<std::size_t>(at.x)] = own(source.x, source.y, source.z);
            }
        }
        for (const int cy : {0, last}) {
            for (const int cx : {0, last}) {
                const int ix = cx == 0 ? 1 : last - 1;  // the corner's neighbours inside and on the border
                const int iy = cy == 0 ? 1 : last - 1;
                bordered[static_cast<std::size_t>(cy) * row + static_cast<std::size_t>(cx)] =
                    meanTexel(bordered[static_cast<std::size_t>(iy) * row + static_cast<std::size_t>(ix)],
                              bordered[static_cast<std::size_t>(cy) * row + static_cast<std::size_t>(ix)],
                              bordered[static_cast<std::size_t>(iy) * row + static_cast<std::size_t>(cx)]);
            }
        }
    }
    return out;
}

glm::vec3 environmentRadiance(const EnvironmentTexels& environment, glm::vec3 dir) {
    const cubemap::CubeTexelFootprint f = cubemap::cubeTexelFootprint(cubemap::cubeFacePoint(dir), environment.faceSize);
    const std::size_t below = environment.faceSize + 2u;
    const std::uint32_t* t = environment.texels.data() + f.first;
    const glm::vec3 top = glm::mix(texelRadiance(t[0]), texelRadiance(t[1]), f.weight.x);
    const glm::vec3 bottom = glm::mix(texelRadiance(t[below]), texelRadiance(t[below + 1]), f.weight.x);
    return glm::mix(top, bottom, f.weight.y);
}

}  // namespace vkrt
