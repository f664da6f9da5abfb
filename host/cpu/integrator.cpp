#include "integrator.h"

#include <cmath>

#include "dielectric.h"
#include "emitter_sampling.h"
#include "ray_offset.h"
#include "sampling.h"
#include "shading.h"
#include "texture.h"

namespace vkrt::cpu {

namespace {

// docs/RENDERING.md §6: a branch contributing less than this (times a radiance that is O(1) in the
// course's scenes) is below a quarter of an 8-bit step, so it is not traced.
constexpr float kMinBranchWeight = 1.0f / 1024.0f;

// docs/RENDERING.md §4: a shadow ray (direction q - origin, so t = 1 is the light point q) stops
// just short of the light, so the geometry a light sits on (a ceiling panel) does not shadow it.
constexpr float kShadowRayEnd = 1.0f - 1.0f / 65536.0f;

bool worthTracing(const glm::vec3& weight) {
    return glm::max(weight.x, glm::max(weight.y, weight.z)) >= kMinBranchWeight;
}

glm::vec3 textured(const Scene& scene, glm::vec3 colour, int texture, glm::vec2 uv) {
    return texture == kNoTexture ? colour : colour * sampleTexture(scene.textures[texture], uv);
}

}  // namespace

Integrator::Integrator(const RenderContext& context) : ctx_(context) {
    for (const LightSource& light : ctx_.lights) hasAreaLights_ |= light.type == LightType::Area;
}

std::uint32_t Integrator::pickEmitterFor(int depth, SampleKey key, std::uint32_t index) const {
    const EmitterTable& table = ctx_.lighting->emitters;
    if (table.records.size() == 1) return 0u;
    return pickEmitter(table, sampling::sample1D(ctx_.sampler, ctx_.lightGrid, key.pixel, index,
                                                 sampling::dimEmitterChoice(static_cast<std::uint32_t>(depth)), key.seed));
}

glm::vec2 Integrator::lightSample(int depth, SampleKey key, std::uint32_t index, std::uint32_t ordinal) const {
    return sampling::sample2D(ctx_.sampler, ctx_.lightGrid, key.pixel, index,
                              sampling::dimLight(static_cast<std::uint32_t>(depth), ordinal), key.seed);
}

void Integrator::drawEarlyLightSample(int depth, SampleKey key) {
    const bool emitters = !ctx_.lighting->emitters.records.empty();
    if (!hasAreaLights_ && !emitters) return;
    const std::uint32_t index = key.sample * ctx_.lightSamples;  // sample j = 0
    early_.pixel = key.pixel, early_.sample = key.sample, early_.seed = key.seed, early_.depth = depth;
    if (hasAreaLights_) early_.area = lightSample(depth, key, index, 0u);
    if (emitters) {
        early_.emitter = pickEmitterFor(depth, key, index);
        early_.emitterSample =
            lightSample(depth, key, index, gpu::emitterLightOrdinal(ctx_.lighting->emitters.records[early_.emitter]));
    }
}

glm::vec3 Integrator::cameraRadiance(const bvh::Ray& ray, SampleKey key) {
    ++counts_.camera;
    return trace(ray, 0, glm::vec3(1.0f), key);
}

glm::vec3 Integrator::trace(const bvh::Ray& ray, int depth, glm::vec3 weight, SampleKey key, float bouncePdf) {
    bvh::Ray timed = ray;
    timed.time = key.time;
    bvh::Hit hit;
    drawEarlyLightSample(depth, key);
    if (!bvh::intersectClosest(ctx_.accel->bvh, timed, hit)) return escaped(timed.dir, bouncePdf);
    return shade(timed, hit, depth, weight, key, bouncePdf);
}

glm::vec3 Integrator::escaped(const glm::vec3& dir, float bouncePdf) const {
    if (!ctx_.environment) return ctx_.background;  // never light-sampled: always seen in full
    const glm::vec3 radiance = environmentRadiance(ctx_.lighting->environment, dir);
    if (!(bouncePdf > 0.0f)) return radiance;
    if (!diffuseWeighs()) return glm::vec3(0.0f);  // next-event estimation counted it already
    const float lightPdf = static_cast<float>(ctx_.lightSamples) * vkrt::environmentPdf(ctx_.lighting->environmentLights, dir);
    return radiance * emitters::misWeight(bouncePdf, lightPdf, ctx_.estimator == Estimator::MisPower);
}

glm::vec3 Integrator::environmentLight(const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng, int depth,
                                       SampleKey key) {
    const bool weighs = diffuseWeighs();
    const float k = static_cast<float>(ctx_.lightSamples);
    const std::uint32_t dim = sampling::dimEnvironment(static_cast<std::uint32_t>(depth));
    glm::vec3 sum(0.0f);
    for (std::uint32_t j = 0; j < ctx_.lightSamples; ++j) {
        const glm::vec2 u = sampling::sample2D(ctx_.sampler, ctx_.lightGrid, key.pixel, key.sample * ctx_.lightSamples + j,
                                               dim, key.seed);
        const EnvironmentSample s = sampleEnvironment(ctx_.lighting->environmentLights, u);
        const float cosine = glm::dot(n, s.direction);
        // No light from inside the surface, as for the bounce.
        if (cosine <= 0.0f || glm::dot(s.direction, ng) <= 0.0f) continue;
        const float w = weighs ? emitters::misWeight(k * s.pdf, emitters::cosinePdf(n, s.direction),
                                                     ctx_.estimator == Estimator::MisPower)
                               : 1.0f;
        if (!(w > 0.0f)) continue;
        ++counts_.shadow;
        bvh::Ray shadow;
        shadow.origin = offsetRayOrigin(sp.position, sideOf(ng, s.direction), sp.errorMagnitude);
        shadow.dir = s.direction;
        shadow.time = key.time;
        if (bvh::intersectAny(ctx_.accel->bvh, shadow)) continue;
        sum += environmentRadiance(ctx_.lighting->environment, s.direction) * (w * cosine * emitters::EMITTER_INV_PI / s.pdf);
    }
    return sum / k;
}

glm::vec3 Integrator::emitted(const bvh::Ray& ray, const SurfacePoint& sp, float bouncePdf) const {
    const glm::vec3 radiance = glm::vec3(ctx_.lighting->emitters.records[static_cast<std::size_t>(sp.emitter)].radiance);
    if (!(bouncePdf > 0.0f)) return radiance;  // not a Diffuse bounce that sampled lights: seen in full
    if (!diffuseWeighs()) return glm::vec3(0.0f);  // next-event estimation counted it already
    const gpu::EmitterRecord& r = ctx_.lighting->emitters.records[static_cast<std::size_t>(sp.emitter)];
    const float lightPdf = static_cast<float>(ctx_.lightSamples) * gpu::emitterChoicePdf(r) *
                           emitterPdf(ctx_.lighting->emitters, r, ray.origin, sp.position, sp.geometricNormal);
    return radiance * emitters::misWeight(bouncePdf, lightPdf, ctx_.estimator == Estimator::MisPower);
}

bool Integrator::occluded(const glm::vec3& origin, const glm::vec3& lightPoint, float time) {
    ++counts_.shadow;
    bvh::Ray shadow;
    shadow.origin = origin;
    shadow.dir = lightPoint - origin;
    shadow.tmax = kShadowRayEnd;
    shadow.time = time;
    return bvh::intersectAny(ctx_.accel->bvh, shadow);
}

glm::vec3 Integrator::shade(const bvh::Ray& ray, const bvh::Hit& hit, int depth, glm::vec3 weight, SampleKey key,
                             float bouncePdf) {
    const Scene& scene = *ctx_.scene;
    const SurfacePoint sp = describeHit(*ctx_.accel, scene, ray, hit);
    if (sp.emitter >= 0) return emitted(ray, sp, bouncePdf);
    const Shader& shader = scene.shaders[sp.shader];
    if (shader.type == ShaderType::Dielectric) return dielectric(ray, hit, shader, sp, depth, weight, key);

    // Two-sided shading: Ng faces the incoming ray, N lies on Ng's side (surface.h keeps them together).
    const bool backFacing = glm::dot(sp.geometricNormal, ray.dir) > 0.0f;
    const glm::vec3 ng = backFacing ? -sp.geometricNormal : sp.geometricNormal;
    const glm::vec3 n = backFacing ? -sp.shadingNormal : sp.shadingNormal;
    const glm::vec3 view = -ray.dir;
    const glm::vec3 kd = textured(scene, shader.diffuse, shader.diffuseTexture, sp.uv);
    const glm::vec3 ks = textured(scene, shader.specular, shader.specularTexture, sp.uv);
    const float m = shader.mirrorCoef;

    switch (shader.type) {
    case ShaderType::Lambertian:
        if (shader.diffuseBounce) return diffuse(shader, sp, n, ng, kd, depth, weight, key);
        return directLight(shader, sp, n, ng, view, kd, ks, depth, key);
    case ShaderType::BlinnPhong:
    case ShaderType::CoolToWarm:
        return directLight(shader, sp, n, ng, view, kd, ks, depth, key);
    case ShaderType::Mirror:
        return reflection(ray, sp, n, ng, shader.roughness, depth, weight, key);
    case ShaderType::Glaze: {
        const glm::vec3 local = directLight(shader, sp, n, ng, view, kd, ks, depth, key);
        return local + m * reflection(ray, sp, n, ng, shader.roughness, depth, weight * m, key);
    }
    case ShaderType::BlinnPhongMirrored: {
        const glm::vec3 local = directLight(shader, sp, n, ng, view, kd, ks, depth, key);
        return (1.0f - m) * local + m * reflection(ray, sp, n, ng, shader.roughness, depth, weight * m, key);
    }
    case ShaderType::Dielectric:
        break;  // handled above
    }
    return glm::vec3(0.0f);
}

glm::vec3 Integrator::directLight(const Shader& shader, const SurfacePoint& sp, const glm::vec3& n,
                                  const glm::vec3& ng, const glm::vec3& view, const glm::vec3& kd,
                                  const glm::vec3& ks, int depth, SampleKey key) {
    const bool shadowed = shader.type != ShaderType::CoolToWarm;
    const bool specular = shader.type == ShaderType::BlinnPhong || shader.type == ShaderType::BlinnPhongMirrored;

    // The contribution of one light point q with intensity I.
    auto contribution = [&](const glm::vec3& q, const glm::vec3& intensity) -> glm::vec3 {
        const glm::vec3 toLight = q - sp.position;
        const float distance = glm::length(toLight);
        if (!(distance > 0.0f)) return glm::vec3(0.0f);  // a light exactly on the point: no direction
        const glm::vec3 l = toLight / distance;
        if (!shadowed) return coolToWarm(kd, intensity, n, l);
        if (glm::dot(n, l) <= 0.0f) return glm::vec3(0.0f);
        const glm::vec3 origin = offsetRayOrigin(sp.position, sideOf(ng, l), sp.errorMagnitude);
        if (occluded(origin, q, key.time)) return glm::vec3(0.0f);
        glm::vec3 c = lambertian(kd, intensity, n, l);
        if (specular) c += blinnPhongSpecular(ks, shader.phongExp, intensity, n, l, view);
        return c;
    };

    const bool early = hasEarlyLightSample(depth, key);
    glm::vec3 sum(0.0f);
    for (const LightSource& light : ctx_.lights) {
        if (light.type == LightType::Point) {
            sum += contribution(light.position, light.intensity);
            continue;
        }
        glm::vec3 lightSum(0.0f);
        for (std::uint32_t j = 0; j < ctx_.lightSamples; ++j) {
            const glm::vec2 s = j == 0 && light.areaOrdinal == 0 && early
                                    ? early_.area
                                    : lightSample(depth, key, key.sample * ctx_.lightSamples + j, light.areaOrdinal);
            lightSum += contribution(lightPoint(light, s), light.intensity);
        }
        sum += lightSum / static_cast<float>(ctx_.lightSamples);
    }

    // Shape emitters, as a continuum of the course's point lights: a sample of density p (per
    // steradian) stands for intensity L / (pi p), so a Lambertian receiver gets kd / pi times the
    // integral of L cos over the emitter's solid angle: what a Diffuse bounce that hits it sees.
    const bool isDiffuse = shader.diffuseBounce;
    if (ctx_.lighting->emitters.records.empty() || (isDiffuse && !diffuseSamplesLights())) return sum;
    // Each of the k light samples goes to one emitter, chosen by its share of the emitters' power
    // (RENDERING.md §4); the sample's density includes that share.
    const bool weighs = isDiffuse && diffuseWeighs();
    const float k = static_cast<float>(ctx_.lightSamples);
    const EmitterTable& table = ctx_.lighting->emitters;
    glm::vec3 emitterSum(0.0f);
    for (std::uint32_t j = 0; j < ctx_.lightSamples; ++j) {
        const std::uint32_t index = key.sample * ctx_.lightSamples + j;
        const bool drawn = j == 0 && early;
        const std::uint32_t e = drawn ? early_.emitter : pickEmitterFor(depth, key, index);
        const gpu::EmitterRecord& r = table.records[e];
        const glm::vec2 u = drawn ? early_.emitterSample : lightSample(depth, key, index, gpu::emitterLightOrdinal(r));
        const emitters::EmitterSample s = sampleEmitter(table, r, sp.position, u);
        const float pdf = gpu::emitterChoicePdf(r) * s.pdf;
        if (!(pdf > 0.0f) || !std::isfinite(pdf)) continue;
        float w = 1.0f;
        if (weighs) {
            // The bounce reaches this direction with its cosine density, or not at all below
            // the geometric surface (diffuse() does not trace those).
            const glm::vec3 l = glm::normalize(s.point - sp.position);
            const float bouncePdf = glm::dot(l, ng) > 0.0f ? emitters::cosinePdf(n, l) : 0.0f;
            w = emitters::misWeight(k * pdf, bouncePdf, ctx_.estimator == Estimator::MisPower);
        }
        if (w > 0.0f) emitterSum += contribution(s.point, glm::vec3(r.radiance) * (w * emitters::EMITTER_INV_PI / pdf));
    }
    return sum + emitterSum / k;
}

glm::vec3 Integrator::diffuse(const Shader& shader, const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng,
                              const glm::vec3& kd, int depth, glm::vec3 weight, SampleKey key) {
    // Every light a Diffuse surface reflects, its direct light included, is a bounce: none at the
    // maximum depth (so -k 0 shows emitters and the environment only).
    if (depth >= ctx_.maxDepth) return glm::vec3(0.0f);
    // One cosine-weighted bounce per pixel sample: f cos / pdf = (kd / pi) cos / (cos / pi) = kd.
    // Drawn before the light samples, whose shadow rays hide the Sobol sample's latency (a chain
    // of ~15 dependent multiplies) that the bounce would otherwise wait for.
    const bool bounces = depth + 1 < ctx_.maxDepth || ctx_.finalRays.bounceSeesLight;
    const glm::vec2 u = bounces ? sampling::sample2D(ctx_.sampler, ctx_.pixelGrid, key.pixel, key.sample,
                                                     sampling::dimBounce(static_cast<std::uint32_t>(depth)), key.seed)
                                : glm::vec2(0.0f);
    glm::vec3 radiance = directLight(shader, sp, n, ng, n, kd, glm::vec3(0.0f), depth, key);
    if (ctx_.environment && diffuseSamplesLights()) radiance += kd * environmentLight(sp, n, ng, depth, key);
    // A bounce ending at the maximum depth where it can find no light is not traced (final_rays.h).
    if (!bounces) return radiance;

    const glm::vec3 dir = emitters::cosineDirection(n, u);
    if (glm::dot(dir, ng) <= 0.0f) return radiance;  // no light from inside
    // Russian roulette where the path's weight has fallen below its depth's threshold (RENDERING.md §5).
    glm::vec3 carried = kd;
    const glm::vec3 bounceWeight = weight * kd;
    const float m = glm::max(bounceWeight.x, glm::max(bounceWeight.y, bounceWeight.z));
    const float threshold = emitters::rouletteThreshold(static_cast<std::uint32_t>(depth));
    if (m < threshold) {
        const float u = sampling::sample1D(ctx_.sampler, ctx_.pixelGrid, key.pixel, key.sample,
                                           sampling::dimRoulette(static_cast<std::uint32_t>(depth)), key.seed);
        const float factor = emitters::rouletteFactor(m, threshold, u);
        if (!(factor > 0.0f)) return radiance;
        carried *= factor;
    }
    ++counts_.bounce;
    bvh::Ray next;
    next.origin = offsetRayOrigin(sp.position, sideOf(ng, dir), sp.errorMagnitude);
    next.dir = dir;
    const float bouncePdf = diffuseSamplesLights() ? std::max(emitters::cosinePdf(n, dir), 1e-30f) : 0.0f;
    return radiance + carried * trace(next, depth + 1, weight * carried, key, bouncePdf);
}

glm::vec3 Integrator::reflection(const bvh::Ray& ray, const SurfacePoint& sp, const glm::vec3& n, const glm::vec3& ng,
                                 float roughness, int depth, glm::vec3 weight, SampleKey key) {
    if (depth >= ctx_.maxDepth) return glm::vec3(0.0f);
    if (depth + 1 >= ctx_.maxDepth && !ctx_.finalRays.reflectionSeesLight) return glm::vec3(0.0f);  // final_rays.h
    const glm::vec3 r = mirrorDirection(ray.dir, n);

    auto traceFrom = [&](const glm::vec3& dir, const glm::vec3& branchWeight) -> glm::vec3 {
        // A direction below the surface would start inside the object: no light comes from there.
        if (glm::dot(dir, ng) <= 0.0f || !worthTracing(branchWeight)) return glm::vec3(0.0f);
        ++counts_.reflection;
        bvh::Ray next;
        next.origin = offsetRayOrigin(sp.position, sideOf(ng, dir), sp.errorMagnitude);
        next.dir = dir;
        return trace(next, depth + 1, branchWeight, key);
    };

    if (roughness == 0.0f) return traceFrom(r, weight);

    // g directions fan out at primary hits only; deeper glossy hits take one direction from the
    // pixel grid, so the ray count stays linear in the depth (RENDERING.md §2).
    const bool fanOut = depth == 0;
    const std::uint32_t g = fanOut ? ctx_.glossSamples : 1u;
    const glm::uvec4& grid = fanOut ? ctx_.glossGrid : ctx_.pixelGrid;
    const float invG = 1.0f / static_cast<float>(g);
    const std::uint32_t dim = sampling::dimGloss(static_cast<std::uint32_t>(depth));
    glm::vec3 sum(0.0f);
    for (std::uint32_t j = 0; j < g; ++j) {
        const glm::vec2 s = sampling::sample2D(ctx_.sampler, grid, key.pixel, key.sample * g + j, dim, key.seed);
        sum += traceFrom(glossyDirection(r, roughness, s), weight * invG);
    }
    return sum / static_cast<float>(g);
}

glm::vec3 Integrator::dielectric(const bvh::Ray& ray, const bvh::Hit& hit, const Shader& shader,
                                 const SurfacePoint& sp, int depth, glm::vec3 weight, SampleKey key) {
    const bool entering = glm::dot(ray.dir, sp.geometricNormal) < 0.0f;
    const float eta = shader.refractiveIndex;
    const float n1 = entering ? 1.0f : eta;
    const float n2 = entering ? eta : 1.0f;
    // Beer-Lambert over the distance travelled inside, applied where the ray leaves the medium.
    const glm::vec3 transmittance = entering ? glm::vec3(1.0f) : beerLambert(shader.attenuation, hit.t);
    const glm::vec3 n = entering ? sp.shadingNormal : -sp.shadingNormal;  // faces the incoming ray
    const float f = fresnelDielectric(-glm::dot(ray.dir, n), n1, n2);
    const glm::vec3 here = weight * transmittance;

    glm::vec3 reflected(0.0f), refracted(0.0f);
    bool traced = false;
    // A path-traced scene continues one branch, reflection with probability f, each carrying the
    // whole weight (f / f): the same expectation as both, at the cost of one path (RENDERING.md §6).
    bool reflects = f > 0.0f, refracts = f < 1.0f;
    float reflectedShare = f, refractedShare = 1.0f - f;
    // Neither branch is traced where it would end at the maximum depth and find no light (final_rays.h).
    if (depth < ctx_.maxDepth && (depth + 1 < ctx_.maxDepth || ctx_.finalRays.reflectionSeesLight)) {
        if (ctx_.dielectricOneBranch && reflects && refracts) {
            reflects = sampling::sample1D(ctx_.sampler, ctx_.pixelGrid, key.pixel, key.sample,
                                          sampling::dimRoulette(static_cast<std::uint32_t>(depth)), key.seed) < f;
            refracts = !reflects;
            reflectedShare = refractedShare = 1.0f;
        }
        if (reflects && worthTracing(here * reflectedShare)) {
            ++counts_.reflection;
            bvh::Ray next;
            next.dir = mirrorDirection(ray.dir, n);
            next.origin = offsetRayOrigin(sp.position, sideOf(sp.geometricNormal, next.dir), sp.errorMagnitude);
            reflected = trace(next, depth + 1, here * reflectedShare, key);
            traced = true;
        }
        if (refracts && worthTracing(here * refractedShare)) {
            bvh::Ray next;
            next.dir = refractDirection(ray.dir, n, n1, n2);
            bool transmits = true;
            if (shader.roughness > 0.0f) {
                // Glossy translucency (RENDERING.md §6): the refracted direction perturbed as gloss
                // perturbs the mirror one, one direction per pixel sample; a direction that leaves
                // on the incoming side carries no light.
                const glm::vec2 s = sampling::sample2D(ctx_.sampler, ctx_.pixelGrid, key.pixel, key.sample,
                                                       sampling::dimTranslucency(static_cast<std::uint32_t>(depth)), key.seed);
                next.dir = glossyDirection(next.dir, shader.roughness, s);
                transmits = glm::dot(next.dir, n) < 0.0f;
            }
            if (transmits) {
                ++counts_.refraction;
                next.origin = offsetRayOrigin(sp.position, sideOf(sp.geometricNormal, next.dir), sp.errorMagnitude);
                refracted = trace(next, depth + 1, here * refractedShare, key);
                traced = true;
            }
        }
    }
    // No branch traced: no light, as in the kernel, where such a hit emits no ray (transmittance
    // times 0 would be NaN where an attenuation above 1 has overflowed it).
    if (!traced) return glm::vec3(0.0f);
    return transmittance * (reflectedShare * reflected + refractedShare * refracted);
}

}  // namespace vkrt::cpu
