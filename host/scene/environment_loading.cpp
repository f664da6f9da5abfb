#include "environment_loading.h"

#include <cstdlib>
#include <utility>

#include "cube_map.h"
#include "input_limits.h"
#include "texture_loading.h"

namespace vkrt {

namespace {

constexpr const char* kFaceSuffix[6] = {"posX", "negX", "posY", "negY", "posZ", "negZ"};

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// Mean absolute difference per channel (0-255) of two RGBA8 texels, alpha left out.
double texelDifference(std::uint32_t a, std::uint32_t b) {
    int sum = 0;
    for (int shift = 0; shift < 24; shift += 8)
        sum += std::abs(static_cast<int>((a >> shift) & 0xffu) - static_cast<int>((b >> shift) & 0xffu));
    return sum / 3.0;
}

void mirrorLeftRight(std::vector<std::uint32_t>& face, int n) {
    for (int y = 0; y < n; ++y) {
        std::uint32_t* row = face.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(n);
        for (int x = 0; x < n / 2; ++x) std::swap(row[x], row[n - 1 - x]);
    }
}

}  // namespace

// Measured on ../shared/scenes/json/images/uffizi_cross.png by tests/lighting (the orientation
// with the smallest seam error over the cube's 12 edges among all 8^6; docs/RENDERING.md §10.3).
const std::array<CrossCell, 6> kVerticalCross = {{
    {2, 1, false, true, false},   // +X: right of the centre, mirrored left-right
    {0, 1, false, true, false},   // -X: left of the centre, mirrored left-right
    {1, 0, false, false, true},   // +Y: top, mirrored top-bottom
    {1, 2, false, false, true},   // -Y: below the centre, mirrored top-bottom
    {1, 3, false, false, true},   // +Z: bottom, mirrored top-bottom
    {1, 1, false, true, false},   // -Z: the centre, mirrored left-right
}};

double edgeSeamError(const CubeFaces& faces, int faceSize, int face, int edge) {
    const int n = faceSize;
    double sum = 0.0;
    for (int i = 1; i <= n; ++i) {
        // The border texel across the edge (bordered coordinates) and the face's own texel beside it.
        const int bx = edge == 0 ? 0 : edge == 1 ? n + 1 : i;
        const int by = edge == 2 ? 0 : edge == 3 ? n + 1 : i;
        const int ox = edge == 0 ? 0 : edge == 1 ? n - 1 : i - 1;
        const int oy = edge == 2 ? 0 : edge == 3 ? n - 1 : i - 1;
        const glm::uvec3 source = cubemap::cubeBorderSource(static_cast<std::uint32_t>(face), bx, by, static_cast<std::uint32_t>(n));
        const std::uint32_t across = faces[source.x][static_cast<std::size_t>(source.y) + static_cast<std::size_t>(source.z) * n];
        const std::uint32_t own = faces[static_cast<std::size_t>(face)][static_cast<std::size_t>(ox) + static_cast<std::size_t>(oy) * n];
        sum += texelDifference(own, across);
    }
    return sum / n;
}

NegZSeams measureNegZSeams(CubeFaces& faces, int faceSize) {
    const int negZ = static_cast<int>(cubemap::CUBE_NEG_Z);
    auto meanOfEdges = [&] {
        double sum = 0.0;
        for (int edge = 0; edge < 4; ++edge) sum += edgeSeamError(faces, faceSize, negZ, edge);
        return sum / 4.0;
    };
    // Mirrored in place and back: a copy of the faces (24 MB for the course's) cost 160 ms here,
    // the two mirrorings 2 ms.
    NegZSeams seams;
    seams.asOpenGL = meanOfEdges();
    mirrorLeftRight(faces[negZ], faceSize);
    seams.mirrored = meanOfEdges();
    mirrorLeftRight(faces[negZ], faceSize);
    return seams;
}

std::optional<Environment> loadCubeFaceEnvironment(const std::string& prefix, NegZRule negZ, EnvironmentProblem& problem) {
    Environment environment;
    std::string firstPath;
    for (int face = 0; face < 6; ++face) {
        const std::string path = prefix + kFaceSuffix[face] + ".png";
        std::string error;
        std::optional<Texture> image = loadTextureImage(path, error);
        if (!image) {
            problem = {std::string("cannot load environment map face ") + kFaceSuffix[face] + " (" + error + ")", path};
            return std::nullopt;
        }
        if (image->width != image->height) {
            problem = {"environment map face is not square (" + sizeText(image->width, image->height) + ")", path};
            return std::nullopt;
        }
        if (face == 0) {
            environment.faceSize = image->width;
            firstPath = path;
        } else if (image->width != environment.faceSize) {
            problem = {"environment map faces differ in size (" + sizeText(image->width, image->height) + ", " +
                           kFaceSuffix[0] + " is " + sizeText(environment.faceSize, environment.faceSize) + ")",
                       path};
            return std::nullopt;
        }
        // Six faces each within the per-image limit could still add up to 6 x 128 MiB: the six
        // together get what one image may have (the course's largest set is 6 x 1024^2 texels).
        // Known from the first face, before the other five are read.
        if (face == 0 && std::size_t(6) * static_cast<std::size_t>(environment.faceSize) *
                static_cast<std::size_t>(environment.faceSize) > inputLimits().imageTexels) {
            problem = {"the six environment map faces of " + sizeText(environment.faceSize, environment.faceSize) +
                           " hold more than the " + std::to_string(inputLimits().imageTexels) + " texels vkrt loads for one map" +
                           inputLimitHint("image-texels"),
                       path};
            return std::nullopt;
        }
        environment.faces[static_cast<std::size_t>(face)] = std::move(image->rgba8);
    }
    bool mirror = negZ == NegZRule::Mirrored;
    if (negZ == NegZRule::Measure) {
        const NegZSeams seams = measureNegZSeams(environment.faces, environment.faceSize);
        environment.negZSeamErrorAsOpenGL = seams.asOpenGL;
        environment.negZSeamErrorMirrored = seams.mirrored;
        mirror = seams.mirrored < seams.asOpenGL;
    }
    if (mirror) mirrorLeftRight(environment.faces[cubemap::CUBE_NEG_Z], environment.faceSize);
    environment.negZMirrored = mirror;
    return environment;
}

std::vector<std::uint32_t> crossFace(const Texture& image, const CrossCell& cell, int k) {
    std::vector<std::uint32_t> face(static_cast<std::size_t>(k) * static_cast<std::size_t>(k));
    for (int y = 0; y < k; ++y) {
        for (int x = 0; x < k; ++x) {
            const int u = cell.transpose ? y : x;
            const int v = cell.transpose ? x : y;
            const int cx = cell.column * k + (cell.flipX ? k - 1 - u : u);
            const int cy = cell.row * k + (cell.flipY ? k - 1 - v : v);
            face[static_cast<std::size_t>(y) * k + x] =
                image.rgba8[static_cast<std::size_t>(cy) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(cx)];
        }
    }
    return face;
}

std::optional<Environment> loadVerticalCrossEnvironment(const std::string& path, EnvironmentProblem& problem) {
    std::string error;
    const std::optional<Texture> image = loadTextureImage(path, error);
    if (!image) {
        problem = {"cannot load the environment map's vertical cross (" + error + ")", path};
        return std::nullopt;
    }
    const int k = image->width / 3;
    if (k == 0 || image->width != 3 * k || image->height != 4 * k) {
        problem = {"a vertical cross is 3k x 4k texels, this image is " + sizeText(image->width, image->height), path};
        return std::nullopt;
    }
    Environment environment;
    environment.faceSize = k;
    for (std::size_t face = 0; face < 6; ++face) environment.faces[face] = crossFace(*image, kVerticalCross[face], k);
    return environment;
}

}  // namespace vkrt
