#include "region_masks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bvh.h"
#include "camera.h"
#include "dielectric.h"
#include "emitter_sampling.h"
#include "emitter_table.h"
#include "lights.h"
#include "ray_offset.h"
#include "shading.h"
#include "surface.h"

namespace vkrt::study {

namespace {

// Two primary hits on one object whose shading normals differ by more than this are an edge (a box
// corner, a crease); smooth curvature across one pixel stays far below it at any useful resolution.
constexpr float kEdgeNormalDegrees = 30.0f;
// docs/RENDERING.md §4: shadow rays stop just short of the light point.
constexpr float kShadowRayEnd = 1.0f - 1.0f / 65536.0f;
// docs/RENDERING.md §6: the renderers do not trace a reflection or refraction whose weight is below
// this; the probes that follow them to Diffuse surfaces stop there too.
constexpr float kMinBranchWeight = 1.0f / 1024.0f;

struct ObjectId {
    bool hit = false;
    std::uint32_t instance = 0;
    const Shape* shape = nullptr;
    bool operator==(const ObjectId&) const = default;
};

// The pixel's entry in every mask.
struct PixelFlags {
    std::uint8_t edge = 0, penumbra = 0, gloss = 0, defocus = 0, motion = 0, indirect = 0, emitter = 0;
};

// A shader that traces a reflection ray: a Mirror, or Glaze / BlinnPhongMirrored with mirrorCoef > 0.
bool reflects(const Shader& shader) {
    return shader.type == ShaderType::Mirror ||
           ((shader.type == ShaderType::Glaze || shader.type == ShaderType::BlinnPhongMirrored) && shader.mirrorCoef > 0.0f);
}

// Gloss and glossy translucency (a rough Dielectric) blur the same way, so they share the region.
bool reflectsGlossily(const Shader& shader) {
    return (reflects(shader) || shader.type == ShaderType::Dielectric) && shader.roughness > 0.0f;
}

bool shadowed(const Shader& shader) {
    return shader.type != ShaderType::CoolToWarm && shader.type != ShaderType::Dielectric &&
           shader.type != ShaderType::Mirror;  // a pure mirror has no direct light to shadow
}

// The course's Diffuse, which the renderers path-trace (host/cpu/integrator.cpp: a Lambertian
// with the bounce).
bool pathTraced(const Shader& shader) { return shader.type == ShaderType::Lambertian && shader.diffuseBounce; }

// What a light probe point does for a surface point.
enum class Reach { Behind, Visible, Hidden };

class PixelProber {
public:
    PixelProber(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, const ProbeOptions& probe)
        : scene_(scene),
          accel_(accel),
          frame_(cpu::makeCameraFrame(scene.cameras.at(options.camera), options.width, options.height)),
          lights_(cpu::makeLightSources(scene)),
          emitters_(accel.lighting ? accel.lighting->emitters : buildEmitterTable(scene)),
          probe_(probe),
          shutter_(shutterOf(options)),
          maxDepth_(options.maxDepth),
          moving_(!accel.bvh.motions.empty()),
          pathTracing_(std::any_of(scene.shaders.begin(), scene.shaders.end(), pathTraced)) {}

    // Every mask's entry of pixel (i, j).
    PixelFlags probe(int i, int j) const {
        PixelFlags flags;
        const int n = probe_.pixelProbes;
        std::vector<int> visible(lightCount(), 0), tested(lightCount(), 0);
        ObjectId first;
        glm::vec3 firstNormal(0.0f);
        bool differs = false;
        // Probes on a grid that includes the pixel's borders (0, 1/(n-1), ..., 1): an edge that
        // crosses the pixel anywhere but through a sliver between probes separates two of them.
        auto at = [n](int k) { return n == 1 ? 0.5f : static_cast<float>(k) / static_cast<float>(n - 1); };
        for (int s = 0; s < n * n; ++s) {
            const glm::vec2 offset(at(s % n), at(s / n));
            bvh::Ray ray = cpu::cameraRay(frame_, i, j, offset);
            ray.time = shutter_.x;
            if (frame_.thinLens && !flags.defocus) flags.defocus = defocused(i, j, offset);
            if (moving_ && !flags.motion) flags.motion = moves(ray);
            if (pathTracing_ && !(flags.indirect && flags.emitter)) findDiffuse(ray, 0, 1.0f, flags);
            bvh::Hit hit;
            ObjectId id;
            glm::vec3 normal(0.0f);
            if (bvh::intersectClosest(accel_.bvh, ray, hit)) {
                id = {true, hit.instance, accel_.origin(hit.instance, hit.prim).shape};
                const cpu::SurfacePoint sp = cpu::describeHit(accel_, scene_, ray, hit);
                const bool backFacing = glm::dot(sp.geometricNormal, ray.dir) > 0.0f;
                const glm::vec3 ng = backFacing ? -sp.geometricNormal : sp.geometricNormal;
                normal = backFacing ? -sp.shadingNormal : sp.shadingNormal;
                if (sp.emitter < 0) {  // an emitter's surface has no shader: it neither reflects nor is lit
                    const Shader& shader = scene_.shaders[sp.shader];
                    if (reflectsGlossily(shader)) flags.gloss = 1;
                    if (shadowed(shader)) countVisibility(sp.position, normal, ng, visible, tested);
                }
            }
            if (s == 0) {
                first = id;
                firstNormal = normal;
            } else if (!(id == first) ||
                       (id.hit && glm::dot(normal, firstNormal) < std::cos(glm::radians(kEdgeNormalDegrees)))) {
                differs = true;
            }
        }
        flags.edge = differs ? 1 : 0;
        for (std::size_t l = 0; l < lightCount(); ++l)
            if (mixed(visible[l], tested[l])) flags.penumbra = 1;
        return flags;
    }

private:
    // What a ray hits (object and point), at the ray's time.
    struct Seen {
        ObjectId id;
        glm::vec3 point{0.0f};
    };
    Seen see(const bvh::Ray& ray) const {
        Seen seen;
        bvh::Hit hit;
        if (bvh::intersectClosest(accel_.bvh, ray, hit)) {
            seen.id = {true, hit.instance, accel_.origin(hit.instance, hit.prim).shape};
            seen.point = ray.origin + hit.t * ray.dir;
        }
        return seen;
    }

    // World size of one pixel at distance `depth` along the gaze.
    float pixelFootprint(float depth) const {
        const float atUnitDepth = frame_.planeWidth / static_cast<float>(frame_.nx);
        return frame_.type == CameraType::Orthographic ? atUnitDepth : atUnitDepth * depth / frame_.focalLength;
    }

    // The pinhole ray's hit spreads into a circle of confusion of A |d - D| / d on the focus plane
    // (docs/RENDERING.md §1): a pixel or more of it is blur; so is a silhouette that rays from
    // opposite points of the lens's rim see on different objects.
    bool defocused(int i, int j, glm::vec2 offset) const {
        bvh::Ray pinhole = cpu::cameraRay(frame_, i, j, offset);  // the lens centre
        pinhole.time = shutter_.x;  // the pose every other mask sees
        const Seen centre = see(pinhole);
        if (centre.id.hit) {
            const float depth = glm::dot(centre.point - pinhole.origin, -frame_.w);
            if (depth > 0.0f) {
                const float circle = 2.0f * frame_.lensRadius * std::abs(depth - frame_.focusDistance) / depth;
                if (circle >= pixelFootprint(frame_.focusDistance)) return true;
            }
        }
        for (const glm::vec2 rim : {glm::vec2(0.0f, 0.5f), glm::vec2(1.0f, 0.5f), glm::vec2(0.5f, 0.0f), glm::vec2(0.5f, 1.0f)}) {
            bvh::Ray ray = cpu::cameraRay(frame_, i, j, offset, rim);
            ray.time = shutter_.x;
            if (!(see(ray).id == centre.id)) return true;
        }
        return false;
    }

    // The same primary ray at the shutter's open, middle and close: a different object, or a hit
    // that moved by a pixel's footprint or more, is motion blur.
    bool moves(bvh::Ray ray) const {
        ray.time = shutter_.x;
        const Seen open = see(ray);
        for (const float t : {0.5f * (shutter_.x + shutter_.y), shutter_.y}) {
            ray.time = t;
            const Seen later = see(ray);
            if (!(later.id == open.id)) return true;
            if (open.id.hit) {
                const float depth = std::max(glm::dot(open.point - ray.origin, -frame_.w), 0.0f);
                if (glm::length(later.point - open.point) >= pixelFootprint(depth)) return true;
            }
        }
        return false;
    }

    // The lights a surface point is probed for: the scene's point and area lights, then its shape emitters.
    std::size_t lightCount() const { return lights_.size() + emitters_.records.size(); }
    static bool mixed(int visible, int tested) { return visible > 0 && visible < tested; }

    // Probe point s (of lightProbes^2) of light l seen from x; nullopt when the sample has no point.
    // An area light's points are its strata's centres. An emitter's follow a Fibonacci lattice
    // (u.x = (s + 1/2) / N, u.y the golden-ratio sequence) through the renderers' own light
    // sampling (emitter_sampling.h), so N points pick N different triangles of a mesh emitter (a
    // grid's N^(1/2) values of u.x would pick only that many); only where they are matters here,
    // not their density.
    std::optional<glm::vec3> lightProbe(std::size_t l, const glm::vec3& x, int s) const {
        const int m = probe_.lightProbes;
        if (l < lights_.size()) {
            if (lights_[l].type == LightType::Point) return lights_[l].position;
            return cpu::lightPoint(lights_[l], glm::vec2((static_cast<float>(s % m) + 0.5f) / static_cast<float>(m),
                                                         (static_cast<float>(s / m) + 0.5f) / static_cast<float>(m)));
        }
        const gpu::EmitterRecord& r = emitters_.records[l - lights_.size()];
        const float k = static_cast<float>(s) + 0.5f;
        const glm::vec2 u(k / static_cast<float>(m * m), k * 0.618034f - std::floor(k * 0.618034f));
        const emitters::EmitterSample sample = sampleEmitter(emitters_, r, x, u);
        if (!(sample.pdf > 0.0f) || !std::isfinite(sample.pdf)) return std::nullopt;
        return sample.point;
    }
    int probesOf(std::size_t l) const {
        return l < lights_.size() && lights_[l].type == LightType::Point ? 1 : probe_.lightProbes * probe_.lightProbes;
    }

    // Whether light point q of light l lights the surface point p (shading normal n, geometric ng):
    // Behind when q is not in front of the surface (the renderers take no sample there) or, for an
    // emitter, when its own surface hides q (its far side, which is not where its light comes from).
    Reach reach(std::size_t l, const glm::vec3& p, const glm::vec3& n, const glm::vec3& ng, const glm::vec3& q) const {
        const glm::vec3 toLight = q - p;
        if (!(glm::length(toLight) > 0.0f) || glm::dot(n, toLight) <= 0.0f) return Reach::Behind;
        bvh::Ray shadow;
        shadow.origin = cpu::offsetRayOrigin(p, cpu::sideOf(ng, toLight));
        shadow.dir = q - shadow.origin;
        shadow.tmax = kShadowRayEnd;
        shadow.time = shutter_.x;  // the occluders where the primary probe saw the scene
        if (l < lights_.size()) return bvh::intersectAny(accel_.bvh, shadow) ? Reach::Hidden : Reach::Visible;
        bvh::Hit hit;
        if (!bvh::intersectClosest(accel_.bvh, shadow, hit)) return Reach::Visible;
        const int self = static_cast<int>(l - lights_.size());
        return accel_.emitterOf(hit.instance) == self ? Reach::Behind : Reach::Hidden;
    }

    // Light points of every light seen from one primary hit: how many of those in front of the
    // surface are unoccluded. A light already seen both lit and hidden from this pixel is a
    // penumbra whatever the rest say, so it is not probed again.
    void countVisibility(const glm::vec3& p, const glm::vec3& n, const glm::vec3& ng, std::vector<int>& visible,
                         std::vector<int>& tested) const {
        for (std::size_t l = 0; l < lightCount(); ++l) {
            if (mixed(visible[l], tested[l])) continue;
            for (int s = 0; s < probesOf(l); ++s) {
                const std::optional<glm::vec3> q = lightProbe(l, p, s);
                if (!q) continue;
                const Reach r = reach(l, p, n, ng, *q);
                if (r == Reach::Behind) continue;
                ++tested[l];
                if (r == Reach::Visible) ++visible[l];
            }
        }
    }

    // Whether some shape emitter lights the surface point p (some probe point in front of it and unoccluded).
    bool seesEmitter(const glm::vec3& p, const glm::vec3& n, const glm::vec3& ng) const {
        for (std::size_t l = lights_.size(); l < lightCount(); ++l)
            for (int s = 0; s < probesOf(l); ++s)
                if (const std::optional<glm::vec3> q = lightProbe(l, p, s); q && reach(l, p, n, ng, *q) == Reach::Visible)
                    return true;
        return false;
    }

    // Follows a probe ray to the first Diffuse surfaces it reaches, through the reflections and
    // refractions the renderers trace (a reflecting shader's mirror direction, a Dielectric's
    // mirror and refracted directions; glossy ones by their unperturbed centre), each one a level
    // deeper, while the branch's weight (m, F, 1 - F) stays traceable. A Diffuse hit below the
    // maximum depth is path traced (indirect); it is an emitter pixel when a shape emitter lights it.
    void findDiffuse(const bvh::Ray& ray, int depth, float weight, PixelFlags& flags) const {
        bvh::Hit hit;
        if (!bvh::intersectClosest(accel_.bvh, ray, hit)) return;
        const cpu::SurfacePoint sp = cpu::describeHit(accel_, scene_, ray, hit);
        if (sp.emitter >= 0) return;  // seen in full by every estimator
        const Shader& shader = scene_.shaders[sp.shader];
        const bool backFacing = glm::dot(sp.geometricNormal, ray.dir) > 0.0f;
        const glm::vec3 ng = backFacing ? -sp.geometricNormal : sp.geometricNormal;
        const glm::vec3 n = backFacing ? -sp.shadingNormal : sp.shadingNormal;
        if (depth >= maxDepth_) return;  // black (Diffuse, docs/RENDERING.md §5) or traced no further
        if (pathTraced(shader)) {
            flags.indirect = 1;
            if (!flags.emitter && seesEmitter(sp.position, n, ng)) flags.emitter = 1;
            return;
        }
        auto follow = [&](const glm::vec3& dir, float branchWeight) {
            if (branchWeight < kMinBranchWeight || (flags.indirect && flags.emitter)) return;
            bvh::Ray next;
            next.origin = cpu::offsetRayOrigin(sp.position, cpu::sideOf(sp.geometricNormal, dir), sp.errorMagnitude);
            next.dir = dir;
            next.time = ray.time;
            findDiffuse(next, depth + 1, branchWeight, flags);
        };
        const glm::vec3 d = glm::normalize(ray.dir);
        if (shader.type == ShaderType::Dielectric) {
            const bool entering = glm::dot(d, sp.geometricNormal) < 0.0f;
            const float n1 = entering ? 1.0f : shader.refractiveIndex;
            const float n2 = entering ? shader.refractiveIndex : 1.0f;
            const glm::vec3 facing = entering ? sp.shadingNormal : -sp.shadingNormal;
            const float f = cpu::fresnelDielectric(-glm::dot(d, facing), n1, n2);
            follow(cpu::mirrorDirection(d, facing), weight * f);
            if (f < 1.0f) follow(cpu::refractDirection(d, facing, n1, n2), weight * (1.0f - f));
        } else if (reflects(shader)) {
            const glm::vec3 r = cpu::mirrorDirection(d, n);
            if (glm::dot(r, ng) > 0.0f) follow(r, shader.type == ShaderType::Mirror ? weight : weight * shader.mirrorCoef);
        }
    }

    const Scene& scene_;
    const SceneAccel& accel_;
    cpu::CameraFrame frame_;
    std::vector<cpu::LightSource> lights_;
    EmitterTable emitters_;
    ProbeOptions probe_;
    glm::vec2 shutter_;
    int maxDepth_;
    bool moving_;
    bool pathTracing_;  // the scene has a Diffuse shader: the indirect and emitter regions can be non-empty
};

}  // namespace

RegionMasks findRegions(const Scene& scene, const SceneAccel& accel, const RenderOptions& options,
                        const ProbeOptions& probe) {
    if (options.width < 1 || options.height < 1)
        throw std::invalid_argument("region masks: image size " + std::to_string(options.width) + "x" +
                                    std::to_string(options.height) + " has no pixels");
    if (options.camera < 0 || options.camera >= static_cast<int>(scene.cameras.size()))
        throw std::invalid_argument("region masks: camera " + std::to_string(options.camera) + " does not exist");
    if (probe.pixelProbes < 1 || probe.lightProbes < 1)
        throw std::invalid_argument("region masks: probe counts must be at least 1");

    RegionMasks masks;
    masks.width = options.width;
    masks.height = options.height;
    const std::size_t pixels = static_cast<std::size_t>(options.width) * options.height;
    masks.edge.assign(pixels, 0);
    masks.penumbra.assign(pixels, 0);
    masks.gloss.assign(pixels, 0);
    masks.defocus.assign(pixels, 0);
    masks.motion.assign(pixels, 0);
    masks.indirect.assign(pixels, 0);
    masks.emitter.assign(pixels, 0);

    const PixelProber prober(scene, accel, options, probe);
    std::atomic<int> nextRow{0};
    auto worker = [&] {
        for (int j = nextRow++; j < options.height; j = nextRow++)
            for (int i = 0; i < options.width; ++i) {
                const std::size_t k = static_cast<std::size_t>(j) * options.width + i;
                const PixelFlags f = prober.probe(i, j);
                masks.edge[k] = f.edge;
                masks.penumbra[k] = f.penumbra;
                masks.gloss[k] = f.gloss;
                masks.defocus[k] = f.defocus;
                masks.motion[k] = f.motion;
                masks.indirect[k] = f.indirect;
                masks.emitter[k] = f.emitter;
            }
    };
    const int threads = std::clamp(probe.threads > 0 ? probe.threads : static_cast<int>(std::thread::hardware_concurrency()),
                                   1, options.height);
    std::vector<std::jthread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    return masks;
}

std::size_t countPixels(const PixelMask& mask) {
    return static_cast<std::size_t>(std::count(mask.begin(), mask.end(), std::uint8_t{1}));
}

Image masksToImage(const RegionMasks& masks) {
    Image image(masks.width, masks.height);
    for (std::size_t k = 0; k < image.pixels.size(); ++k) {
        const int bits = masks.edge[k] | masks.penumbra[k] << 1 | masks.gloss[k] << 2 | masks.defocus[k] << 3 |
                         masks.motion[k] << 4 | masks.indirect[k] << 5 | masks.emitter[k] << 6;
        image.pixels[k] = glm::vec3(static_cast<float>(bits) / 255.0f, 0.0f, 0.0f);
    }
    return image;
}

RegionMasks masksFromImage(const Image& image) {
    RegionMasks masks;
    masks.width = image.width;
    masks.height = image.height;
    for (const glm::vec3& c : image.pixels) {
        const int bits = static_cast<int>(std::lround(c.r * 255.0f));
        masks.edge.push_back(bits & 1);
        masks.penumbra.push_back((bits >> 1) & 1);
        masks.gloss.push_back((bits >> 2) & 1);
        masks.defocus.push_back((bits >> 3) & 1);
        masks.motion.push_back((bits >> 4) & 1);
        masks.indirect.push_back((bits >> 5) & 1);
        masks.emitter.push_back((bits >> 6) & 1);
    }
    return masks;
}

Image regionsPicture(const RegionMasks& masks) {
    const int panel = masks.width + 2;  // a 2-pixel grey gap between the panels
    Image image(3 * masks.width + 4, masks.height);
    for (int j = 0; j < masks.height; ++j) {
        for (int i = 0; i < masks.width; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * masks.width + i;
            image.at(i, j) = glm::vec3(masks.edge[k], masks.penumbra[k], masks.gloss[k]);
            image.at(panel + i, j) = glm::vec3(masks.defocus[k], masks.motion[k], 0.0f);
            image.at(2 * panel + i, j) = glm::vec3(masks.indirect[k], masks.emitter[k], 0.0f);
        }
        for (int gap : {masks.width, masks.width + 1, panel + masks.width, panel + masks.width + 1})
            image.at(gap, j) = glm::vec3(0.5f);
    }
    return image;
}

}  // namespace vkrt::study
