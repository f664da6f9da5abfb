#include "path_tracing_support.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "both_paths.h"
#include "scene_building.h"

namespace vkrt::stability {

Shader diffuse(glm::vec3 kd) {
    Shader s = lambertian(kd);
    s.diffuseBounce = true;
    return s;
}

namespace {

void addEmitter(Scene& scene, Emitter emitter) {
    emitter.lightsBefore = static_cast<int>(scene.lights.size());  // listed after the lights so far
    scene.emitters.push_back(emitter);
}

}  // namespace

void addSphereEmitter(Scene& scene, glm::vec3 centre, float radius, glm::vec3 radiance) {
    addWorldEmitter(scene, sphere(centre, radius, -1), radiance);
}

void addWorldEmitter(Scene& scene, const Shape& shape, glm::vec3 radiance) {
    Emitter emitter;
    emitter.radiance = radiance;
    emitter.shape = shape;
    emitter.shape.shader = -1;
    addEmitter(scene, emitter);
}

void addPlacedEmitter(Scene& scene, Shape prototype, const glm::mat4& toWorld, glm::vec3 radiance) {
    // A prototype always has a shader in a file; an emitter's hit never uses it (§4).
    if (prototype.shader < 0) prototype.shader = add(scene, lambertian(glm::vec3(0.0f)));
    scene.prototypes.push_back(prototype);
    Emitter emitter;
    emitter.radiance = radiance;
    emitter.prototype = static_cast<int>(scene.prototypes.size()) - 1;
    emitter.shape.shader = -1;
    emitter.objectToWorld = toWorld;
    addEmitter(scene, emitter);
}

Mesh unitQuad() {
    Mesh mesh;
    mesh.positions = {{-0.5f, 0.0f, -0.5f}, {0.5f, 0.0f, -0.5f}, {0.5f, 0.0f, 0.5f}, {-0.5f, 0.0f, 0.5f}};
    mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
    generateNormals(mesh);
    return mesh;
}

Shape meshShape(int mesh) {
    Shape shape;
    shape.type = ShapeType::Mesh;
    shape.mesh = mesh;
    return shape;
}

RenderOptions pathOptions(int size, int rpp, int maxDepth, Estimator estimator) {
    RenderOptions o = smallOptions(size, size, rpp);
    o.maxDepth = maxDepth;
    o.estimator = estimator;
    return o;
}

Camera topView(float half, float height) {
    Camera c = orthographic({0.0f, height, 0.0f}, {0.0f, -1.0f, 0.0f}, 2.0f * half);
    c.up = glm::vec3(0.0f, 0.0f, -1.0f);
    return c;
}

Image expectedTopView(int n, float half, const PlaneRadiance& f, int kSub) {
    Image image(n, n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            glm::dvec3 sum(0.0);
            for (int b = 0; b < kSub; ++b)
                for (int a = 0; a < kSub; ++a) {
                    const double x = half * (2.0 * (i + (a + 0.5) / kSub) / n - 1.0);
                    const double z = half * (2.0 * (j + (b + 0.5) / kSub) / n - 1.0);
                    sum += f(glm::dvec3(x, 0.0, z));
                }
            image.at(i, j) = glm::vec3(sum / double(kSub * kSub));
        }
    return image;
}

double sphereCosineIntegral(glm::dvec3 p, glm::dvec3 n, glm::dvec3 centre, double radius) {
    const glm::dvec3 toCentre = centre - p;
    const double d = glm::length(toCentre);
    const double cosTheta = glm::dot(n, toCentre) / d;
    // Only a sphere wholly above the horizon (its nearest approach to the tangent plane, d cos,
    // larger than r) has this closed form; the tests never ask for another.
    if (!(d * cosTheta > radius)) return NAN;
    return std::numbers::pi * (radius / d) * (radius / d) * cosTheta;
}

double polygonCosineIntegral(glm::dvec3 p, glm::dvec3 n, const std::vector<glm::dvec3>& corners) {
    double sum = 0.0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 a = glm::normalize(corners[i] - p), b = glm::normalize(corners[(i + 1) % corners.size()] - p);
        const glm::dvec3 c = glm::cross(a, b);
        const double sine = glm::length(c);
        if (sine == 0.0) continue;
        sum += std::atan2(sine, glm::dot(a, b)) * glm::dot(n, c / sine);
    }
    return 0.5 * std::fabs(sum);
}

std::vector<glm::dvec3> ellipsoidSilhouette(glm::dvec3 p, const glm::dmat4& unitSphereToWorld, int sides) {
    const glm::dvec3 q = glm::dvec3(glm::inverse(unitSphereToWorld) * glm::dvec4(p, 1.0));
    const double q2 = glm::dot(q, q);
    const glm::dvec3 centre = q / q2;                  // the tangent points' circle: its centre,
    const double radius = std::sqrt(1.0 - 1.0 / q2);   // radius, and plane (perpendicular to q)
    const glm::dvec3 axis = glm::normalize(q);
    const glm::dvec3 e1 = glm::normalize(glm::cross(axis, std::fabs(axis.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 e2 = glm::cross(axis, e1);
    std::vector<glm::dvec3> corners;
    for (int k = 0; k < sides; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / sides;
        const glm::dvec3 onSphere = centre + radius * (std::cos(phi) * e1 + std::sin(phi) * e2);
        corners.push_back(glm::dvec3(unitSphereToWorld * glm::dvec4(onSphere, 1.0)));
    }
    return corners;
}

std::string NoiseComparison::describe() const {
    std::ostringstream s;
    s << failing << " of " << values << " over |z| limit, worst |z| " << worstZ << ", whole-region z " << meanZ
      << ", relative bias " << relativeBias;
    if (!first.empty()) s << "; first: " << first;
    return s.str();
}

NoiseComparison compareWithNoise(const Estimate& a, const Estimate& b, int block, double zLimit, double floor,
                                 const std::function<bool(int x, int y)>& use, double absoluteFloor) {
    const Image& ma = *a.mean;
    const Image& mb = *b.mean;
    auto varianceOfMean = [](const Estimate& e, int x, int y, int c) {
        return e.sampleVariance ? double(e.sampleVariance->at(x, y)[c]) / e.rpp : 0.0;
    };
    NoiseComparison r;
    double sumDiff = 0.0, sumB = 0.0, sumVar = 0.0;
    for (int by = 0; by < ma.height; by += block)
        for (int bx = 0; bx < ma.width; bx += block)
            for (int c = 0; c < 3; ++c) {
                double sa = 0.0, sb = 0.0, var = 0.0;
                int count = 0;
                for (int y = by; y < std::min(by + block, ma.height); ++y)
                    for (int x = bx; x < std::min(bx + block, ma.width); ++x) {
                        if (use && !use(x, y)) continue;
                        sa += ma.at(x, y)[c];
                        sb += mb.at(x, y)[c];
                        var += varianceOfMean(a, x, y, c) + varianceOfMean(b, x, y, c);
                        ++count;
                    }
                if (count == 0) continue;
                sumDiff += sa - sb;
                sumB += sb;
                sumVar += var;
                const double diff = (sa - sb) / count, meanB = sb / count;
                const double variance = var / (double(count) * count) + (floor * meanB) * (floor * meanB) + absoluteFloor * absoluteFloor;
                const double z = variance > 0.0 ? std::fabs(diff) / std::sqrt(variance) : (diff == 0.0 ? 0.0 : INFINITY);
                ++r.values;
                r.worstZ = std::max(r.worstZ, z);
                if (z <= zLimit) continue;
                if (r.failing++ == 0) {
                    char text[200];
                    std::snprintf(text, sizeof text, "block at (%d, %d) channel %d: %.6g against %.6g, z %.3g", bx, by, c,
                                  sa / count, meanB, z);
                    r.first = text;
                }
            }
    r.meanZ = sumVar > 0.0 ? sumDiff / std::sqrt(sumVar) : 0.0;
    r.relativeBias = sumB != 0.0 ? sumDiff / sumB : 0.0;
    return r;
}

double zLimitFor(int tests, double alpha) {
    const double level = -std::expm1(std::log1p(-alpha) / tests);
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > level ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace vkrt::stability
