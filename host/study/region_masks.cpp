#include "region_masks.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bvh.h"
#include "camera.h"
#include "lights.h"
#include "ray_offset.h"
#include "surface.h"

namespace vkrt::study {

namespace {

// Two primary hits on one object whose shading normals differ by more than this are an edge (a box
// corner, a crease); smooth curvature across one pixel stays far below it at any useful resolution.
constexpr float kEdgeNormalDegrees = 30.0f;
// docs/RENDERING.md §4: shadow rays stop just short of the light point.
constexpr float kShadowRayEnd = 1.0f - 1.0f / 65536.0f;

struct ObjectId {
    bool hit = false;
    std::uint32_t instance = 0;
    const Shape* shape = nullptr;
    bool operator==(const ObjectId&) const = default;
};

// Gloss and glossy translucency (a rough Dielectric) blur the same way, so they share the region.
bool reflectsGlossily(const Shader& shader) {
    const bool reflects = shader.type == ShaderType::Mirror || shader.type == ShaderType::Dielectric ||
                          ((shader.type == ShaderType::Glaze || shader.type == ShaderType::BlinnPhongMirrored) &&
                           shader.mirrorCoef > 0.0f);
    return reflects && shader.roughness > 0.0f;
}

bool shadowed(const Shader& shader) {
    return shader.type != ShaderType::CoolToWarm && shader.type != ShaderType::Dielectric &&
           shader.type != ShaderType::Mirror;  // a pure mirror has no direct light to shadow
}

class PixelProber {
public:
    PixelProber(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, const ProbeOptions& probe)
        : scene_(scene),
          accel_(accel),
          frame_(cpu::makeCameraFrame(scene.cameras.at(options.camera), options.width, options.height)),
          lights_(cpu::makeLightSources(scene)),
          probe_(probe),
          shutter_(shutterOf(options)),
          moving_(!accel.bvh.motions.empty()) {}

    // Fills the masks' entries of pixel (i, j).
    void probe(int i, int j, std::uint8_t& edge, std::uint8_t& penumbra, std::uint8_t& gloss, std::uint8_t& defocus,
               std::uint8_t& motion) const {
        const int n = probe_.pixelProbes;
        std::vector<int> visible(lights_.size(), 0), tested(lights_.size(), 0);
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
            if (frame_.thinLens && !defocus) defocus = defocused(i, j, offset);
            if (moving_ && !motion) motion = moves(ray);
            bvh::Hit hit;
            ObjectId id;
            glm::vec3 normal(0.0f);
            if (bvh::intersectClosest(accel_.bvh, ray, hit)) {
                id = {true, hit.instance, accel_.origin(hit.instance, hit.prim).shape};
                const cpu::SurfacePoint sp = cpu::describeHit(accel_, scene_, ray, hit);
                const bool backFacing = glm::dot(sp.geometricNormal, ray.dir) > 0.0f;
                const glm::vec3 ng = backFacing ? -sp.geometricNormal : sp.geometricNormal;
                normal = backFacing ? -sp.shadingNormal : sp.shadingNormal;
                const Shader& shader = scene_.shaders[sp.shader];
                if (reflectsGlossily(shader)) gloss = 1;
                if (shadowed(shader)) countVisibility(sp.position, normal, ng, visible, tested);
            }
            if (s == 0) {
                first = id;
                firstNormal = normal;
            } else if (!(id == first) ||
                       (id.hit && glm::dot(normal, firstNormal) < std::cos(glm::radians(kEdgeNormalDegrees)))) {
                differs = true;
            }
        }
        edge = differs ? 1 : 0;
        for (std::size_t l = 0; l < lights_.size(); ++l)
            if (visible[l] > 0 && visible[l] < tested[l]) penumbra = 1;
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

    // Light points of every light seen from one primary hit: how many of those in front of the
    // surface are unoccluded.
    void countVisibility(const glm::vec3& p, const glm::vec3& n, const glm::vec3& ng, std::vector<int>& visible,
                         std::vector<int>& tested) const {
        for (std::size_t l = 0; l < lights_.size(); ++l) {
            const cpu::LightSource& light = lights_[l];
            const int m = light.type == LightType::Point ? 1 : probe_.lightProbes;
            for (int s = 0; s < m * m; ++s) {
                const glm::vec2 u((static_cast<float>(s % m) + 0.5f) / static_cast<float>(m),
                                  (static_cast<float>(s / m) + 0.5f) / static_cast<float>(m));
                const glm::vec3 q = cpu::lightPoint(light, u);
                const glm::vec3 toLight = q - p;
                if (!(glm::length(toLight) > 0.0f) || glm::dot(n, toLight) <= 0.0f) continue;
                ++tested[l];
                bvh::Ray shadow;
                shadow.origin = cpu::offsetRayOrigin(p, cpu::sideOf(ng, toLight));
                shadow.dir = q - shadow.origin;
                shadow.tmax = kShadowRayEnd;
                shadow.time = shutter_.x;  // the occluders where the primary probe saw the scene
                if (!bvh::intersectAny(accel_.bvh, shadow)) ++visible[l];
            }
        }
    }

    const Scene& scene_;
    const SceneAccel& accel_;
    cpu::CameraFrame frame_;
    std::vector<cpu::LightSource> lights_;
    ProbeOptions probe_;
    glm::vec2 shutter_;
    bool moving_;
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

    const PixelProber prober(scene, accel, options, probe);
    std::atomic<int> nextRow{0};
    auto worker = [&] {
        for (int j = nextRow++; j < options.height; j = nextRow++)
            for (int i = 0; i < options.width; ++i) {
                const std::size_t k = static_cast<std::size_t>(j) * options.width + i;
                prober.probe(i, j, masks.edge[k], masks.penumbra[k], masks.gloss[k], masks.defocus[k], masks.motion[k]);
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
        const int bits = masks.edge[k] | masks.penumbra[k] << 1 | masks.gloss[k] << 2 | masks.defocus[k] << 3 | masks.motion[k] << 4;
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
    }
    return masks;
}

Image regionsPicture(const RegionMasks& masks) {
    Image image(2 * masks.width + 2, masks.height);  // a 2-pixel grey gap between the panels
    for (int j = 0; j < masks.height; ++j) {
        for (int i = 0; i < masks.width; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * masks.width + i;
            image.at(i, j) = glm::vec3(masks.edge[k], masks.penumbra[k], masks.gloss[k]);
            image.at(masks.width + 2 + i, j) = glm::vec3(masks.defocus[k], masks.motion[k], 0.0f);
        }
        image.at(masks.width, j) = image.at(masks.width + 1, j) = glm::vec3(0.5f);
    }
    return image;
}

}  // namespace vkrt::study
