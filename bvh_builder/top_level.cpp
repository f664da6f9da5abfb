#include "top_level.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vkrt::bvh {

namespace {

// Row i of the upper 3x4 part of a column-major matrix.
glm::vec4 row(const glm::dmat4& m, int i) {
    return glm::vec4(static_cast<float>(m[0][i]), static_cast<float>(m[1][i]), static_cast<float>(m[2][i]),
                     static_cast<float>(m[3][i]));
}

[[noreturn]] void fail(std::size_t index, const std::string& what) {
    std::ostringstream msg;
    msg << "bvh: instance " << index << ": " << what;
    throw std::invalid_argument(msg.str());
}

}  // namespace

gpu::Instance makeInstance(const InstanceInput& in, std::uint32_t bottomRoot, std::size_t index) {
    const glm::dmat4 m(in.objectToWorld);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r]))
                fail(index, "transform has a non-finite entry at row " + std::to_string(r) + ", column " + std::to_string(c));
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
        fail(index, "transform is not affine (last row must be 0 0 0 1)");
    const glm::dmat3 linear(m);
    const double det = glm::determinant(linear);
    if (det == 0.0 || !std::isfinite(1.0 / det)) fail(index, "transform is singular (determinant " + std::to_string(det) + ")");
    const glm::dmat4 inv = glm::inverse(m);
    const glm::dmat3 normal = glm::transpose(glm::inverse(linear));

    gpu::Instance out{};
    for (int i = 0; i < 3; ++i) {
        out.worldToObject[i] = row(inv, i);
        out.objectToWorld[i] = row(m, i);
        out.normalToWorld[i] = glm::vec4(static_cast<float>(normal[0][i]), static_cast<float>(normal[1][i]),
                                         static_cast<float>(normal[2][i]), 0.0f);
    }
    out.info = {bottomRoot, in.materialOverride, in.group, 0u};
    return out;
}

bool isIdentity(const gpu::Instance& instance) {
    if (gpu::instanceMotionTexel(instance.info) != gpu::MOTION_NONE) return false;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c)
            if (instance.objectToWorld[r][c] != (r == c ? 1.0f : 0.0f) || instance.worldToObject[r][c] != (r == c ? 1.0f : 0.0f))
                return false;
    return true;
}

Aabb worldBounds(const Aabb& objectBox, const glm::mat4& objectToWorld) {
    Aabb out;
    if (objectBox.empty()) return out;
    const glm::dmat4 m(objectToWorld);
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? objectBox.hi.x : objectBox.lo.x, (corner & 2) ? objectBox.hi.y : objectBox.lo.y,
                           (corner & 4) ? objectBox.hi.z : objectBox.lo.z);
        const glm::dvec3 w = glm::dvec3(m * glm::dvec4(p, 1.0));
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
    // The kernels transform the ray (not the box) in float; a relative 2^-20 of the box's largest
    // coordinate covers that rounding with a wide margin while costing no measurable traversal.
    double magnitude = 0.0;
    for (int a = 0; a < 3; ++a) magnitude = std::max({magnitude, std::abs(lo[a]), std::abs(hi[a])});
    const double pad = 0x1p-20 * magnitude;
    for (int a = 0; a < 3; ++a) {
        out.lo[a] = std::nextafter(static_cast<float>(lo[a] - pad), -INFINITY);
        out.hi[a] = std::nextafter(static_cast<float>(hi[a] + pad), INFINITY);
    }
    return out;
}

FlattenResult buildTopLevel(const std::vector<Aabb>& worldBoxes, const SahParams& params, ThreadPool& pool,
                            std::vector<BinaryNode>& nodes) {
    std::vector<PrimRef> refs;
    refs.reserve(worldBoxes.size());
    for (std::size_t i = 0; i < worldBoxes.size(); ++i)
        if (!worldBoxes[i].empty()) refs.push_back(PrimRef::make(worldBoxes[i], static_cast<std::uint32_t>(i)));
    SahParams top = params;
    top.maxLeafSize = 1;
    const BuildTree tree = buildSah(refs, top, pool);
    return flatten(tree, [&](const BuildNode& leaf) { return refs[leaf.first()].id(); }, top, pool, nodes);
}

}  // namespace vkrt::bvh
