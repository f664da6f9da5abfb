#include "geometry_extent.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace vkrt::rules {

namespace {

using glm::dvec3;

double maxAbs(const dvec3& v) { return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}); }

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

dvec3 applyPoint(const glm::mat4& m, const glm::vec3& p) {
    const glm::dmat4 d(m);
    return dvec3(d * glm::dvec4(dvec3(p), 1.0));
}

// Distance from `eye` to the box [lo, hi].
double boxDistance(const dvec3& eye, const dvec3& lo, const dvec3& hi) {
    const dvec3 outside = glm::max(glm::max(lo - eye, eye - hi), dvec3(0.0));
    return glm::length(outside);
}

// What is wrong with a triangle (corners relative to the eye), if anything.
std::optional<std::string> triangleProblem(const dvec3& a, const dvec3& b, const dvec3& c) {
    const double reach = std::max({maxAbs(a), maxAbs(b), maxAbs(c)});
    if (reach > kTriangleReach)
        return "a corner lies " + number(reach) + " from the camera's eye, beyond the " + number(kTriangleReach) +
               " up to which float triangle intersection does not overflow (it multiplies three coordinates); it "
               "may not render";
    // A lower bound on the distance from the eye (the origin here) to the triangle: the larger of
    // the distances to its plane and to its bounding box.
    const dvec3 n = glm::cross(b - a, c - a);
    const double nLength = glm::length(n);
    const double plane = nLength > 0.0 ? std::fabs(glm::dot(n, a)) / nLength : 0.0;
    const double box = boxDistance(dvec3(0.0), glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
    const double distance = std::max(plane, box);
    // The eye exactly in the plane sees the triangle edge-on (nothing of it shows): no warning.
    if (distance > 0.0 && reach > kTriangleSpanPerDistance * distance)
        return "its corners lie up to " + number(reach) + " from the camera's eye but it passes " + number(distance) +
               " from it: float intersection places hits on it only to about 2^-24 x " + number(reach) + " = " +
               number(reach * 0x1p-24) + ", too coarse for what the camera sees nearby; split it into smaller triangles";
    return std::nullopt;
}

struct Reporter {
    const Scene& scene;
    bool strict;
    Diagnostics& diagnostics;
    dvec3 eye;

    void warn(const SourceLocation& where, const std::string& element, const std::string& problem) const {
        Issue issue{where.file.empty() ? scene.path : where.file, where.line, element, problem, "", where.column};
        if (strict) throw SceneError(std::move(issue));
        diagnostics.warn(std::move(issue));
    }

    // The first triangle of a mesh (placed by `toWorld`) with a problem, named by its index.
    std::optional<std::string> meshProblem(const Mesh& mesh, const glm::mat4& toWorld) const {
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
            const glm::uvec3 t = mesh.triangles[i];
            if (const auto p = triangleProblem(applyPoint(toWorld, mesh.positions[t.x]) - eye,
                                               applyPoint(toWorld, mesh.positions[t.y]) - eye,
                                               applyPoint(toWorld, mesh.positions[t.z]) - eye))
                return "triangle " + std::to_string(i) + " of " + mesh.path + ": " + *p;
        }
        return std::nullopt;
    }

    // The shape's object-space bounding box placed by `toWorld`: its world box, relative to the eye.
    std::array<dvec3, 2> worldBox(const Shape& shape, const glm::mat4& toWorld) const {
        glm::vec3 lo(0.0f), hi(0.0f);
        switch (shape.type) {
        case ShapeType::Sphere: lo = shape.center - shape.radius; hi = shape.center + shape.radius; break;
        case ShapeType::Box: lo = shape.minPt; hi = shape.maxPt; break;
        case ShapeType::Triangle:
            lo = glm::min(shape.v0, glm::min(shape.v1, shape.v2));
            hi = glm::max(shape.v0, glm::max(shape.v1, shape.v2));
            break;
        case ShapeType::Mesh: {
            const Mesh& mesh = scene.meshes[shape.mesh];
            if (mesh.positions.empty()) break;
            lo = hi = mesh.positions[0];
            for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
            break;
        }
        }
        dvec3 worldLo(INFINITY), worldHi(-INFINITY);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
            const dvec3 w = applyPoint(toWorld, p) - eye;
            worldLo = glm::min(worldLo, w);
            worldHi = glm::max(worldHi, w);
        }
        return {worldLo, worldHi};
    }

    std::optional<std::string> shapeProblem(const Shape& shape, const glm::mat4& toWorld) const {
        const auto [lo, hi] = worldBox(shape, toWorld);
        const double reach = std::max(maxAbs(lo), maxAbs(hi));
        if (shape.type == ShapeType::Sphere || shape.type == ShapeType::Box) {
            if (reach > kQuadricReach)
                return "it reaches " + number(reach) + " from the camera's eye, beyond the " + number(kQuadricReach) +
                       " up to which float intersection does not overflow (squared distances); it may not render";
            return std::nullopt;
        }
        // No triangle can have a problem when the whole box is near enough, and far enough from the
        // eye for its size (each triangle's distance is at least the box's). An eye inside the box
        // (a room) has each triangle checked.
        const double distance = boxDistance(dvec3(0.0), lo, hi);
        if (reach <= kTriangleReach && distance > 0.0 && reach <= kTriangleSpanPerDistance * distance) return std::nullopt;
        if (shape.type == ShapeType::Triangle)
            return triangleProblem(applyPoint(toWorld, shape.v0) - eye, applyPoint(toWorld, shape.v1) - eye,
                                   applyPoint(toWorld, shape.v2) - eye);
        return meshProblem(scene.meshes[shape.mesh], toWorld);
    }
};

}  // namespace

void warnGeometryBeyondFloat(const Scene& scene, bool strict, Diagnostics& diagnostics) {
    if (scene.cameras.empty()) return;
    const Reporter r{scene, strict, diagnostics, dvec3(scene.cameras[scene.defaultCamera].position)};
    const glm::mat4 identity(1.0f);
    for (const Shape& shape : scene.shapes)
        if (const auto p = r.shapeProblem(shape, identity)) r.warn(shape.where, "shape '" + shape.name + "'", *p);
    for (const Instance& instance : scene.instances)
        if (const auto p = r.shapeProblem(scene.prototypes[instance.prototype], instance.objectToWorld))
            r.warn(instance.where, "instance '" + instance.name + "'", *p);
    for (const Emitter& emitter : scene.emitters) {
        const Shape& shape = emitter.prototype >= 0 ? scene.prototypes[emitter.prototype] : emitter.shape;
        if (const auto p = r.shapeProblem(shape, emitter.objectToWorld)) r.warn(emitter.where, "light '" + emitter.name + "'", *p);
    }
    for (const Light& light : scene.lights) {
        const double size = light.type == LightType::Area ? std::max(light.width, light.length) : 0.0;
        const double reach = maxAbs(dvec3(light.position) - r.eye) + size;
        if (reach > kQuadricReach)
            r.warn(light.where, "light", "it lies " + number(reach) + " from the camera's eye, beyond the " +
                                             number(kQuadricReach) + " up to which float shading does not overflow "
                                             "(the squared light direction); it may light nothing");
    }
}

}  // namespace vkrt::rules
