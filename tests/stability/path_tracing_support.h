// What the path-tracing tests (issue 20; docs/RENDERING.md §4-§5) share: scenes with Diffuse
// surfaces and shape emitters built in code, closed forms of the light an emitter sends a plane,
// computed in double here from radiometry alone (never from the renderers' code), and comparisons
// of a rendered image with a closed form or with another estimator whose tolerance is the noise.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image.h"
#include "render_options.h"
#include "scene.h"

namespace vkrt::stability {

// The course's Diffuse: a Lambertian that also gathers the light other surfaces send it.
Shader diffuse(glm::vec3 kd);

// Shape emitters as the loaders add them (after the lights added so far), so a scene built here is
// the scene a file would give. A world sphere; a world shape; a shape placed by `toWorld` (a
// prototype of its own, as a JSON instance emitter is); a mesh placed by `toWorld`.
void addSphereEmitter(Scene& scene, glm::vec3 centre, float radius, glm::vec3 radiance);
void addWorldEmitter(Scene& scene, const Shape& shape, glm::vec3 radiance);
void addPlacedEmitter(Scene& scene, Shape prototype, const glm::mat4& toWorld, glm::vec3 radiance);

// The unit square in the xz-plane around the origin as two triangles, both wound with normal +y
// (corners in order around it: -x-z, +x-z, +x+z, -x+z).
Mesh unitQuad();
// A mesh shape (for addPlacedEmitter).
Shape meshShape(int mesh);

RenderOptions pathOptions(int size, int rpp, int maxDepth, Estimator estimator);

// An orthographic camera at height `height` looking straight down at the plane y = 0 and seeing
// the square x, z in [-half, half]. Its up vector is (0,0,-1) (RENDERING.md §1; without one a
// straight-down camera has +x at the top), so u = +x and v = -z: pixel (i, j) of an n x n image covers x in half*(2i/n - 1 .. 2(i+1)/n - 1), z likewise
// with j (row 0 at z = -half).
Camera topView(float half, float height);
// The mean of f over each pixel's footprint on y = 0 (a sub x sub midpoint grid per pixel), as an
// image: what the jittered camera samples estimate. The closed forms here vary on the scale of the
// emitter's height, 8 pixels or more, so the midpoint rule's error, ~ (pixel / sub)^2 / 24 of f's
// relative curvature, is below 1e-5 relative at sub = 4.
using PlaneRadiance = std::function<glm::dvec3(glm::dvec3 p)>;
Image expectedTopView(int n, float half, const PlaneRadiance& f, int sub = 8);

// Closed forms (RENDERING.md §4: an emitter lights a Lambertian receiver with
// kd / pi * integral of L cos over its solid angle), for the receiver point p with unit normal n:
//  - a sphere wholly above p's horizon: cosine-weighted solid angle pi (r/d)^2 cos(theta), so the
//    reflected radiance is kd L (r/d)^2 cos(theta);
//  - a polygon (Lambert 1760): integral of cos over its solid angle =
//    (1/2) |sum_i angle(u_i, u_i+1) n . unit(u_i x u_i+1)|, u_i unit vectors to its corners;
//  - an ellipsoid (the unit sphere under the affine map M): the cone of lines through p tangent
//    to it touches it along an ellipse, the image under M of the circle where the lines through
//    M^-1 p touch the unit sphere (affine maps keep tangency); the ellipse as a polygon of `sides`
//    corners gives Lambert's integral (an inscribed polygon loses ~ (2 pi / sides)^2 / 6 of it).
double sphereCosineIntegral(glm::dvec3 p, glm::dvec3 n, glm::dvec3 centre, double radius);
double polygonCosineIntegral(glm::dvec3 p, glm::dvec3 n, const std::vector<glm::dvec3>& corners);
std::vector<glm::dvec3> ellipsoidSilhouette(glm::dvec3 p, const glm::dmat4& unitSphereToWorld, int sides);

// An image estimated from rpp samples per pixel: the mean, and the per-pixel sample variance
// (renderCpu's; both devices compute the same estimator from the same random numbers, so it is
// the GPU's too). No variance: an exact image (a closed form).
struct Estimate {
    const Image* mean = nullptr;
    const Image* sampleVariance = nullptr;
    int rpp = 1;
};

// Two estimates of the same expected image, compared over blocks of block x block pixels (1: per
// pixel): z = (mean_a - mean_b) / sqrt(var_a / rpp_a + var_b / rpp_b + (floor * mean_b)^2), the
// block's variance the sum of its pixels' over the count squared. For a stratified sampler
// var / rpp over-estimates the variance of a mean, so z is conservative. `floor` covers float
// rounding (renderers sum in float) and a closed form's quadrature. Blocks pool samples for an
// estimator whose few hits per pixel make a pixel's own sample variance unreliable (a bounce
// finding a small emitter: a pixel with no hit has variance 0), so the central limit theorem holds.
struct NoiseComparison {
    int values = 0;             // blocks x channels compared
    int failing = 0;            // |z| over the limit
    double worstZ = 0.0;
    double meanZ = 0.0;         // of the whole region's mean
    double relativeBias = 0.0;  // sum(a - b) / sum(b), over all compared pixels and channels
    std::string first;          // the first failing value: block, channel, both means, z
    std::string describe() const;
};
// `use` (optional) picks the pixels compared; a block with none is skipped. `absoluteFloor` (added
// to the standard deviation like `floor * mean_b`) keeps differences far below an 8-bit step from
// failing where an estimator's few hits leave it no variance to judge by.
NoiseComparison compareWithNoise(const Estimate& a, const Estimate& b, int block, double zLimit, double floor,
                                 const std::function<bool(int x, int y)>& use = {}, double absoluteFloor = 0.0);

// The |z| that n independent two-sided tests exceed with a family-wise probability alpha (Sidak).
double zLimitFor(int tests, double alpha);

}  // namespace vkrt::stability
