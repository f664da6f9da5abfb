#include "emitter_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sampling.h"

namespace vkrt {

namespace {

const Shape& shapeOf(const Scene& scene, const Emitter& emitter) {
    return emitter.prototype >= 0 ? scene.prototypes.at(static_cast<std::size_t>(emitter.prototype)) : emitter.shape;
}

// The 3x4 rows of an affine matrix (glm is column-major: row r is m[c][r]).
void rowsOf(const glm::mat4& m, glm::vec4 rows[3]) {
    for (int r = 0; r < 3; ++r) rows[r] = glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
}

// Whether the 3x3 part is a similarity: orthogonal columns of one length. A relative tolerance of
// 1e-5 admits the rounding of a rotation composed from degrees; anything further from a
// similarity is sampled as the ellipsoid it is.
bool isSimilarity(const glm::mat3& a, float& scale) {
    const float l0 = glm::length(a[0]), l1 = glm::length(a[1]), l2 = glm::length(a[2]);
    scale = (l0 + l1 + l2) / 3.0f;
    const float tol = 1e-5f * scale;
    const bool equal = std::fabs(l0 - scale) <= tol && std::fabs(l1 - scale) <= tol && std::fabs(l2 - scale) <= tol;
    const float tol2 = 1e-5f * scale * scale;
    return equal && std::fabs(glm::dot(a[0], a[1])) <= tol2 && std::fabs(glm::dot(a[0], a[2])) <= tol2 &&
           std::fabs(glm::dot(a[1], a[2])) <= tol2;
}

// The world-space triangles of a box, a triangle or a mesh under `toWorld`.
std::vector<glm::vec3> worldTriangles(const Scene& scene, const Shape& shape, const glm::mat4& toWorld) {
    std::vector<glm::vec3> corners;
    auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        for (const glm::vec3& p : {a, b, c}) corners.push_back(glm::vec3(toWorld * glm::vec4(p, 1.0f)));
    };
    switch (shape.type) {
    case ShapeType::Triangle: add(shape.v0, shape.v1, shape.v2); break;
    case ShapeType::Box: {
        const glm::vec3 lo = shape.minPt, hi = shape.maxPt;
        auto corner = [&](int i) { return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z); };
        // Each face as two triangles over its four corners (bit `axis` fixed to `side`).
        for (int axis = 0; axis < 3; ++axis) {
            const int u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3);
            for (int side = 0; side < 2; ++side) {
                const int base = side << axis;
                add(corner(base), corner(base | u), corner(base | u | v));
                add(corner(base), corner(base | u | v), corner(base | v));
            }
        }
        break;
    }
    case ShapeType::Mesh: {
        const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(shape.mesh));
        corners.reserve(mesh.triangles.size() * 3);
        for (const glm::uvec3& t : mesh.triangles) add(mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]);
        break;
    }
    case ShapeType::Sphere: break;
    }
    return corners;
}

// A box's world triangles wound so that e1 x e2 points away from its centre, whatever the
// transform (a mirroring one reverses every winding): emitter_sampling.h triangleFacesPoint.
void windOutwards(std::vector<glm::vec3>& corners, const glm::vec3& centre) {
    for (std::size_t i = 0; i + 2 < corners.size(); i += 3) {
        const glm::dvec3 a(corners[i]), b(corners[i + 1]), c(corners[i + 2]);
        if (glm::dot(glm::cross(b - a, c - a), glm::dvec3(centre) - a) > 0.0) std::swap(corners[i + 1], corners[i + 2]);
    }
}

void addTriangles(EmitterTable& table, gpu::EmitterRecord& record, const std::vector<glm::vec3>& corners) {
    const std::size_t count = corners.size() / 3;
    std::vector<double> areas(count);
    double total = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 a(corners[3 * i]), b(corners[3 * i + 1]), c(corners[3 * i + 2]);
        areas[i] = 0.5 * glm::length(glm::cross(b - a, c - a));
        total += areas[i];
    }
    record.info.x = gpu::EMITTER_TRIANGLES;
    record.info.y = static_cast<std::uint32_t>(table.triangles.size());
    if (!(total > 0.0)) return;  // no area: nothing to sample (and nothing to see)
    record.info.z = static_cast<std::uint32_t>(count);
    record.radiance.w = static_cast<float>(1.0 / total);
    // The triangles' bounding sphere (centre of their box, radius to the farthest corner, rounded
    // up), for the rule that picks solid-angle or area sampling (emitter_sampling.h solidAngleNear).
    glm::dvec3 lo(corners[0]), hi(corners[0]);
    for (const glm::vec3& c : corners) lo = glm::min(lo, glm::dvec3(c)), hi = glm::max(hi, glm::dvec3(c));
    const glm::dvec3 centre = 0.5 * (lo + hi);
    double radius = 0.0;
    for (const glm::vec3& c : corners) radius = std::max(radius, glm::length(glm::dvec3(c) - centre));
    record.sphere = glm::vec4(glm::vec3(centre), static_cast<float>(radius * (1.0 + 1e-6)));
    double running = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        running += areas[i];
        gpu::EmitterTriangle t;
        // The last share is exactly 1, so every u in [0, 1) finds a triangle.
        const float share = i + 1 == count ? 1.0f : static_cast<float>(running / total);
        t.corner = glm::vec4(corners[3 * i], share);
        t.edge1 = glm::vec4(corners[3 * i + 1] - corners[3 * i], 0.0f);
        t.edge2 = glm::vec4(corners[3 * i + 2] - corners[3 * i], 0.0f);
        table.triangles.push_back(t);
    }
}

// An emitter's world area, to estimate its power: a triangle set's is exact, a sphere's 4 pi r^2,
// an ellipsoid's by Knud Thomsen's formula (within 1.1% of the true area) over the lengths of the
// transform's columns, exact for an axis-aligned one and an estimate for a sheared one.
double emitterArea(const gpu::EmitterRecord& r, const glm::mat4& toWorld) {
    const double sphere = 4.0 * std::numbers::pi * double(r.sphere.w) * double(r.sphere.w);
    switch (gpu::emitterKind(r)) {
    case gpu::EMITTER_SPHERE: return sphere;
    case gpu::EMITTER_ELLIPSOID: {
        const glm::mat3 a(toWorld);
        const double x = glm::length(a[0]), y = glm::length(a[1]), z = glm::length(a[2]), p = 1.6075;
        return sphere * std::pow((std::pow(x * y, p) + std::pow(x * z, p) + std::pow(y * z, p)) / 3.0, 1.0 / p);
    }
    default: return gpu::emitterTriangleCount(r) == 0 ? 0.0 : 1.0 / double(r.radiance.w);
    }
}

// Every record's choice share: its power over the total, or 1 / count when no emitter has any
// (black emitters: every light sample then adds nothing, whichever it picks).
void setChoiceShares(EmitterTable& table, const std::vector<double>& powers) {
    double total = 0.0;
    for (double p : powers) total += p;
    const std::size_t n = table.records.size();
    double running = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
        const double share = total > 0.0 ? powers[e] / total : 1.0 / double(n);
        running += share;
        table.records[e].choice.x = static_cast<float>(share);
        table.records[e].choice.y = e + 1 == n ? 1.0f : static_cast<float>(running);
    }
}

}  // namespace

std::uint32_t areaLightCount(const Scene& scene) {
    return static_cast<std::uint32_t>(
        std::count_if(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.type == LightType::Area; }));
}

EmitterTable buildEmitterTable(const Scene& scene) {
    EmitterTable table;
    std::vector<double> powers;
    const std::uint32_t firstOrdinal = areaLightCount(scene);
    // Every area light and emitter draws its samples in a dimension of its own (sampling.h dimLight).
    if (firstOrdinal + scene.emitters.size() > sampling::MAX_LIGHT_ORDINALS)
        throw std::invalid_argument(scene.path + ": " + std::to_string(firstOrdinal) + " area lights and " +
                                    std::to_string(scene.emitters.size()) + " shape emitters; vkrt samples at most " +
                                    std::to_string(sampling::MAX_LIGHT_ORDINALS) + " together (each has a sample dimension of its own)");
    for (std::size_t e = 0; e < scene.emitters.size(); ++e) {
        const Emitter& emitter = scene.emitters[e];
        const Shape& shape = shapeOf(scene, emitter);
        gpu::EmitterRecord record{};
        record.radiance = glm::vec4(emitter.radiance, 0.0f);
        record.info.w = firstOrdinal + static_cast<std::uint32_t>(e);
        if (shape.type == ShapeType::Sphere) {
            const glm::mat3 linear(emitter.objectToWorld);
            float scale = 1.0f;
            if (isSimilarity(linear, scale)) {
                record.info.x = gpu::EMITTER_SPHERE;
                record.sphere = glm::vec4(glm::vec3(emitter.objectToWorld * glm::vec4(shape.center, 1.0f)), shape.radius * scale);
            } else {
                record.info.x = gpu::EMITTER_ELLIPSOID;
                record.sphere = glm::vec4(shape.center, shape.radius);
                rowsOf(emitter.objectToWorld, record.toWorld);
                rowsOf(glm::inverse(emitter.objectToWorld), record.toObject);
                const double det = std::fabs(static_cast<double>(glm::determinant(linear)));
                const double r = shape.radius;
                record.radiance.w = static_cast<float>(1.0 / (4.0 * std::numbers::pi * r * r * det));
            }
        } else {
            std::vector<glm::vec3> corners = worldTriangles(scene, shape, emitter.objectToWorld);
            if (shape.type == ShapeType::Box) {
                // Convex: its light samples go to the faces in front of the point (choice.z).
                windOutwards(corners, glm::vec3(emitter.objectToWorld * glm::vec4(0.5f * (shape.minPt + shape.maxPt), 1.0f)));
                record.choice.z = 1.0f;
            }
            addTriangles(table, record, corners);
        }
        const glm::dvec3 radiance(emitter.radiance);
        const double power = std::max(0.0, (radiance.r + radiance.g + radiance.b) / 3.0) * emitterArea(record, emitter.objectToWorld);
        powers.push_back(std::isfinite(power) ? power : 0.0);
        table.records.push_back(record);
    }
    setChoiceShares(table, powers);
    return table;
}

namespace {

// The kernel's emitterSolidAngle and samplesBySolidAngle (shaders/emitters.glsl): the total solid
// angle of the triangles x's light samples go to, and whether those are only the faces in front
// of x (a convex emitter seen from outside: emitter_sampling.h triangleFacesPoint).
bool samplesBySolidAngle(const EmitterTable& table, const gpu::EmitterRecord& r, const glm::vec3& x, float& omega,
                         bool& onlyFacing) {
    omega = 0.0f;
    onlyFacing = false;
    if (gpu::emitterTriangleCount(r) > emitters::SOLID_ANGLE_MAX_TRIANGLES || !emitters::solidAngleNear(r, x)) return false;
    const std::uint32_t first = gpu::emitterFirstTriangle(r), n = gpu::emitterTriangleCount(r);
    const bool convex = gpu::emitterConvex(r);
    float facing = 0.0f;
    for (std::uint32_t i = 0; i < n; ++i) {
        const gpu::EmitterTriangle& t = table.triangles[first + i];
        const float w = emitters::triangleSolidAngle(t, x);
        omega += w;
        if (convex && emitters::triangleFacesPoint(t, x)) facing += w;
    }
    if (facing > 0.0f) {
        omega = facing;
        onlyFacing = true;
    }
    return omega >= emitters::SOLID_ANGLE_MIN;
}

// The kernel's sampleEmitterBySolidAngle: the triangle whose running solid angle first exceeds
// u.x omega (or the last with any, should rounding leave u.x omega beyond the sum).
emitters::EmitterSample sampleBySolidAngle(const EmitterTable& table, const gpu::EmitterRecord& r, const glm::vec3& x,
                                           glm::vec2 u, float omega, bool onlyFacing) {
    const std::uint32_t first = gpu::emitterFirstTriangle(r), n = gpu::emitterTriangleCount(r);
    if (n == 1) return emitters::sampleSphericalTriangle(table.triangles[first], x, u, omega, 1.0f / omega);
    const float target = u.x * omega;
    float running = 0.0f, chosenStart = 0.0f, chosenOmega = 0.0f;
    std::uint32_t chosen = n;
    for (std::uint32_t i = 0; i < n; ++i) {
        const gpu::EmitterTriangle& t = table.triangles[first + i];
        const float w = onlyFacing && !emitters::triangleFacesPoint(t, x) ? 0.0f : emitters::triangleSolidAngle(t, x);
        if (w > 0.0f) {
            chosen = i, chosenStart = running, chosenOmega = w;
            if (target < running + w) break;
        }
        running += w;
    }
    if (chosen == n) return emitters::EmitterSample{x, glm::vec3(0.0f, 0.0f, 1.0f), 0.0f};
    const float ux = std::clamp((target - chosenStart) / chosenOmega, 0.0f, 0.99999994f);
    return emitters::sampleSphericalTriangle(table.triangles[first + chosen], x, glm::vec2(ux, u.y), chosenOmega, 1.0f / omega);
}

}  // namespace

emitters::EmitterSample sampleEmitter(const EmitterTable& table, const gpu::EmitterRecord& r, const glm::vec3& x,
                                      glm::vec2 u) {
    switch (gpu::emitterKind(r)) {
    case gpu::EMITTER_SPHERE: return emitters::sampleSphereEmitter(x, glm::vec3(r.sphere), r.sphere.w, u);
    case gpu::EMITTER_ELLIPSOID: return emitters::sampleEllipsoidEmitter(r, x, u);
    default: break;
    }
    if (gpu::emitterTriangleCount(r) == 0) return emitters::EmitterSample{x, glm::vec3(0.0f, 0.0f, 1.0f), 0.0f};
    float omega = 0.0f;
    bool onlyFacing = false;
    if (samplesBySolidAngle(table, r, x, omega, onlyFacing)) return sampleBySolidAngle(table, r, x, u, omega, onlyFacing);
    const std::uint32_t i = pickEmitterTriangle(table, r, u.x);
    const float previous = i > gpu::emitterFirstTriangle(r) ? gpu::emitterTriangleCdf(table.triangles[i - 1]) : 0.0f;
    return emitters::sampleEmitterTriangle(table.triangles[i], previous, gpu::emitterAreaPdf(r), x, u);
}

float emitterPdf(const EmitterTable& table, const gpu::EmitterRecord& r, const glm::vec3& x, const glm::vec3& q,
                 const glm::vec3& nq) {
    switch (gpu::emitterKind(r)) {
    case gpu::EMITTER_SPHERE: return emitters::sphereEmitterPdf(x, glm::vec3(r.sphere), r.sphere.w, q, nq);
    case gpu::EMITTER_ELLIPSOID: return emitters::ellipsoidEmitterPdf(r, x, q, nq);
    default: break;
    }
    if (gpu::emitterTriangleCount(r) == 0) return 0.0f;
    float omega = 0.0f;
    bool onlyFacing = false;
    // A face that does not face x gets no light samples (only a grazing ray reaches one).
    if (samplesBySolidAngle(table, r, x, omega, onlyFacing))
        return onlyFacing && !(glm::dot(nq, x - q) > 0.0f) ? 0.0f : 1.0f / omega;
    return emitters::solidAnglePdf(gpu::emitterAreaPdf(r), x, q, nq);
}

std::uint32_t pickEmitter(const EmitterTable& table, float u) {
    const auto first = table.records.begin(), last = table.records.end();
    const auto it = std::upper_bound(first, last, u, [](float x, const gpu::EmitterRecord& r) { return x < r.choice.y; });
    return static_cast<std::uint32_t>(std::min(it, last - 1) - first);
}

std::uint32_t pickEmitterTriangle(const EmitterTable& table, const gpu::EmitterRecord& record, float u) {
    const auto first = table.triangles.begin() + gpu::emitterFirstTriangle(record);
    const auto last = first + gpu::emitterTriangleCount(record);
    const auto it = std::upper_bound(first, last, u, [](float x, const gpu::EmitterTriangle& t) { return x < t.corner.w; });
    return static_cast<std::uint32_t>(std::min(it, last - 1) - table.triangles.begin());
}

}  // namespace vkrt
