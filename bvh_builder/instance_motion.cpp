#include "instance_motion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/quaternion.hpp>

#include "../shaders/shared/motion.h"
#include "bvh.h"
#include "top_level.h"

namespace vkrt::bvh {

namespace {

struct Polar {
    glm::dvec3 translation{0.0};
    glm::dmat3 rotation{1.0};
    glm::dmat3 stretch{1.0};
};

std::optional<std::string> poseProblem(const glm::mat4& m, const char* which) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return std::string(which) + " has a non-finite entry";
    if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
        return std::string(which) + " is not affine (last row must be 0 0 0 1)";
    const double det = glm::determinant(glm::dmat3(glm::dmat4(m)));
    if (det == 0.0 || !std::isfinite(1.0 / det)) return std::string(which) + " is singular";
    return std::nullopt;
}

// L = R * S by the iteration R <- (R + R^-T) / 2 (Higham; pbrt's Transform decomposition), which
// converges quadratically to the orthogonal factor; a mirroring L gives det R = -1, turned into a
// rotation by moving the sign into S (L = (-R) * (-S)).
Polar decompose(const glm::mat4& m) {
    const glm::dmat4 d(m);
    Polar p;
    p.translation = glm::dvec3(d[3]);
    const glm::dmat3 linear(d);
    glm::dmat3 r = linear;
    for (int step = 0; step < 100; ++step) {
        const glm::dmat3 next = 0.5 * (r + glm::transpose(glm::inverse(r)));
        double change = 0.0;
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) change = std::max(change, std::abs(next[c][k] - r[c][k]));
        r = next;
        if (change < 1e-15) break;
    }
    if (glm::determinant(r) < 0.0) r = -r;
    p.rotation = r;
    p.stretch = glm::transpose(r) * linear;
    return p;
}

glm::vec4 rowOf(const glm::dmat3& m, int i) {
    return glm::vec4(static_cast<float>(m[0][i]), static_cast<float>(m[1][i]), static_cast<float>(m[2][i]), 0.0f);
}

glm::vec4 quaternionOf(const glm::dmat3& r) {
    const glm::dquat q = glm::normalize(glm::quat_cast(r));
    return glm::vec4(static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z), static_cast<float>(q.w));
}

// Frobenius norm: bounds the spectral norm, so |S p| <= norm(S) |p|.
double norm(const glm::dmat3& m) {
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) sum += m[c][k] * m[c][k];
    return std::sqrt(sum);
}

glm::mat4 matrixOf(const gpu::Instance& pose) {
    glm::mat4 m(1.0f);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = pose.objectToWorld[r][c];
    return m;
}

glm::dmat3 stretchOf(const glm::vec4 rows[3]) {
    glm::dmat3 s;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) s[c][r] = rows[r][c];
    return s;
}

}  // namespace

std::optional<std::string> motionProblem(const glm::mat4& start, const glm::mat4& end) {
    if (auto problem = poseProblem(start, "the start transform")) return problem;
    if (auto problem = poseProblem(end, "the end transform")) return problem;
    const double a = glm::determinant(glm::dmat3(glm::dmat4(start)));
    const double b = glm::determinant(glm::dmat3(glm::dmat4(end)));
    if ((a < 0.0) != (b < 0.0))
        return std::string("the end transform mirrors the object and the start transform does not (or the reverse): "
                           "no rigid motion with a non-singular stretch joins them");
    return std::nullopt;
}

gpu::InstanceMotion decomposeMotion(const glm::mat4& start, const glm::mat4& end) {
    if (const auto problem = motionProblem(start, end)) throw std::invalid_argument("motion: " + *problem);
    const Polar p0 = decompose(start), p1 = decompose(end);
    gpu::InstanceMotion m{};
    m.rotation0 = quaternionOf(p0.rotation);
    m.rotation1 = quaternionOf(p1.rotation);
    if (glm::dot(m.rotation0, m.rotation1) < 0.0f) m.rotation1 = -m.rotation1;  // the short way round
    const double cosAngle = std::clamp(static_cast<double>(glm::dot(glm::dvec4(m.rotation0), glm::dvec4(m.rotation1))), -1.0, 1.0);
    const double angle = std::acos(cosAngle);
    // Below ~1e-3 rad nlerp and slerp differ by < 1e-10 (far under float's 6e-8): slerp's 1/sin
    // would only add rounding.
    const double invSin = angle > 1e-3 ? 1.0 / std::sin(angle) : 0.0;
    m.translation0 = glm::vec4(glm::vec3(p0.translation), static_cast<float>(angle));
    m.translation1 = glm::vec4(glm::vec3(p1.translation), static_cast<float>(invSin));
    for (int i = 0; i < 3; ++i) {
        m.stretch0[i] = rowOf(p0.stretch, i);
        m.stretch1[i] = rowOf(p1.stretch, i);
    }
    return m;
}

Aabb motionBounds(const Aabb& objectBox, const gpu::InstanceMotion& motion) {
    Aabb out;
    if (objectBox.empty()) return out;
    constexpr int kSteps = 64;
    for (int k = 0; k <= kSteps; ++k) {
        const gpu::Instance pose = motion::instanceAtTime(gpu::Instance{}, motion, static_cast<float>(k) / kSteps);
        out.grow(worldBounds(objectBox, matrixOf(pose)));
    }
    // Speed of a point p of the box: |dT/du| + |dR/du| |S p| + |R dS/du p|, with |dR/du| = twice
    // the quaternion angle (the rotation turns by 2 * angle over the motion).
    double reach = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? objectBox.hi.x : objectBox.lo.x, (corner & 2) ? objectBox.hi.y : objectBox.lo.y,
                           (corner & 4) ? objectBox.hi.z : objectBox.lo.z);
        reach = std::max(reach, glm::length(p));
    }
    const glm::dmat3 s0 = stretchOf(motion.stretch0), s1 = stretchOf(motion.stretch1);
    const double speed = glm::length(glm::dvec3(motion.translation1) - glm::dvec3(motion.translation0)) +
                         2.0 * motion.translation0.w * std::max(norm(s0), norm(s1)) * reach + norm(s1 - s0) * reach;
    // Between two poses 1/kSteps apart a point strays at most half the step times its speed from
    // the straight segment joining them, and the boxes hold both ends.
    const float pad = static_cast<float>(0.5 * speed / kSteps * (1.0 + 1e-6));
    out.lo -= glm::vec3(pad);
    out.hi += glm::vec3(pad);
    return out;
}

const gpu::Instance& instanceAtTime(const SceneBvh& bvh, std::uint32_t i, float time, gpu::Instance& posed) {
    const gpu::Instance& record = bvh.instances[i];
    const std::uint32_t texel = gpu::instanceMotionTexel(record.info);
    if (texel == gpu::MOTION_NONE) return record;
    const std::size_t k = (texel - bvh.instances.size() * gpu::INSTANCE_TEXELS) / gpu::MOTION_TEXELS;
    posed = motion::instanceAtTime(record, bvh.motions[k], time);
    return posed;
}

}  // namespace vkrt::bvh
