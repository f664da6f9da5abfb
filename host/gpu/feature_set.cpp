#include "feature_set.h"

#include <algorithm>

#include "top_level.h"
#include "used_shaders.h"

namespace vkrt {

namespace {

std::uint32_t pathStack(std::uint32_t maxDepth, const RenderOptions& options) {
    // integrator.glsl: only dielectrics (two branches per level where nothing is Diffuse) and
    // depth-0 gloss samples push, so at most maxDepth + glossSamples rays wait; at least one entry
    // keeps the array legal.
    return std::max<std::uint32_t>(1, maxDepth + static_cast<std::uint32_t>(std::max(options.glossSamples, 1)));
}

// A scene where no hit emits a second ray needs no path stack: 0 compiles its push and pop out of
// the kernel. They are not free when unused: lavapipe runs every statement for all 8 lanes whatever
// the branches decide, and a store to the per-lane indexed stack is a per-lane loop of masked
// stores, at each push site (integrator.glsl, host/gpu/README.md).
// A dielectric emits two rays only where no Diffuse surface is rendered: with one, it continues
// one branch (used_shaders.h pathTraced, the frame's PATH_DIELECTRIC_ONE_BRANCH).
std::uint32_t scenePathStack(const FeatureSet& f, const RenderOptions& options) {
    const bool glossFanOut = f.reflection && f.gloss && options.glossSamples > 1;
    const bool dielectricSplits = f.dielectric && !f.diffuse;
    return (dielectricSplits || glossFanOut) ? pathStack(f.maxDepth, options) : 0u;
}

// Which primitive kinds the BVH holds and whether it has a top level to walk.
FeatureSet geometryFeatures(const bvh::SceneBvh& bvh, bool packedNodes) {
    FeatureSet f;
    f.triangles = f.spheres = f.boxes = false;
    for (const gpu::Primitive& p : bvh.prims) {
        const std::uint32_t kind = gpu::primitiveKind(p.a);
        f.triangles |= kind == gpu::PRIM_KIND_TRIANGLE;
        f.spheres |= kind == gpu::PRIM_KIND_SPHERE;
        f.boxes |= kind == gpu::PRIM_KIND_BOX;
    }
    f.instances = needsTopLevel(bvh);
    f.motion = !bvh.motions.empty();
    f.packedNodes = packedNodes;
    return f;
}

}  // namespace

bool needsTopLevel(const bvh::SceneBvh& bvh) { return !(bvh.instances.size() == 1 && bvh::isIdentity(bvh.instances[0])); }

std::array<std::uint32_t, gpu::SPEC_COUNT> FeatureSet::specializationValues(std::uint32_t samplesPerDispatch) const {
    std::array<std::uint32_t, gpu::SPEC_COUNT> v{};
    v[gpu::SPEC_HAS_TRIANGLES] = triangles;
    v[gpu::SPEC_HAS_SPHERES] = spheres;
    v[gpu::SPEC_HAS_BOXES] = boxes;
    v[gpu::SPEC_HAS_INSTANCES] = instances;
    v[gpu::SPEC_HAS_AREA_LIGHTS] = areaLights;
    v[gpu::SPEC_HAS_SPECULAR] = specular;
    v[gpu::SPEC_HAS_REFLECTION] = reflection;
    v[gpu::SPEC_HAS_GLOSS] = gloss;
    v[gpu::SPEC_HAS_DIELECTRIC] = dielectric;
    v[gpu::SPEC_HAS_TEXTURES] = textures;
    v[gpu::SPEC_HAS_COOL_TO_WARM] = coolToWarm;
    v[gpu::SPEC_MAX_DEPTH] = maxDepth;
    v[gpu::SPEC_PATH_STACK_SIZE] = pathStackSize;
    v[gpu::SPEC_PACKED_NODES] = packedNodes;
    v[gpu::SPEC_SAMPLER] = sampler;
    v[gpu::SPEC_SAMPLES_PER_DISPATCH] = samplesPerDispatch;
    v[gpu::SPEC_HAS_THIN_LENS] = thinLens;
    v[gpu::SPEC_HAS_TRANSLUCENCY] = translucency;
    v[gpu::SPEC_HAS_MOTION] = motion;
    v[gpu::SPEC_HAS_DIFFUSE] = diffuse;
    v[gpu::SPEC_HAS_EMITTERS] = emitters;
    v[gpu::SPEC_HAS_ENVIRONMENT] = environment;
    v[gpu::SPEC_ESTIMATOR] = estimator;
    v[gpu::SPEC_ADAPTIVE] = adaptive;
    return v;
}

std::string wavefrontStageName(std::uint32_t stage) {
    static const char* const names[] = {"render", "generate", "extend", "shade-rec", "shadow", "shade-res", "accum"};
    return stage < gpu::WAVEFRONT_STAGE_COUNT ? names[stage] : "stage-" + std::to_string(stage);
}

std::string FeatureSet::describe() const {
    std::string s;
    auto add = [&](bool on, const char* name) {
        if (!on) return;
        if (!s.empty()) s += ' ';
        s += name;
    };
    add(triangles, "triangles");
    add(spheres, "spheres");
    add(boxes, "boxes");
    add(instances, "instances");
    add(areaLights, "area-lights");
    add(specular, "specular");
    add(reflection, "reflection");
    add(gloss, "gloss");
    add(dielectric, "dielectric");
    add(textures, "textures");
    add(coolToWarm, "cool-to-warm");
    add(thinLens, "thin-lens");
    add(translucency, "translucency");
    add(motion, "motion");
    add(diffuse, "diffuse");
    add(emitters, "emitters");
    add(environment, "environment");
    add(adaptive, "adaptive");
    add(wavefrontStage != gpu::WAVEFRONT_OFF, ("wavefront-stage=" + wavefrontStageName(wavefrontStage)).c_str());
    add(diffuse && estimator != gpu::ESTIMATOR_FROM_FRAME,
        ("estimator=" + estimatorName(static_cast<Estimator>(estimator))).c_str());
    add(!packedNodes, "exact-nodes");
    add(sampler != gpu::SAMPLER_FROM_FRAME, ("sampler=" + samplerName(static_cast<SamplerKind>(sampler))).c_str());
    add(true, ("depth=" + std::to_string(maxDepth) + " stack=" + std::to_string(pathStackSize)).c_str());
    return s;
}

FeatureSet deriveFeatureSet(const Scene& scene, const SceneAccel& accel, const RenderOptions& options, bool packedNodes) {
    FeatureSet f = geometryFeatures(accel.bvh, packedNodes);
    f.areaLights = std::any_of(scene.lights.begin(), scene.lights.end(), [](const Light& l) { return l.type == LightType::Area; });

    f.specular = f.reflection = f.gloss = f.dielectric = f.textures = f.coolToWarm = f.translucency = f.diffuse = false;
    for (const int index : usedShaders(scene)) {
        const Shader& s = scene.shaders.at(index);
        f.specular |= s.type == ShaderType::BlinnPhong || s.type == ShaderType::BlinnPhongMirrored;
        f.reflection |= s.type == ShaderType::Mirror || s.type == ShaderType::Glaze || s.type == ShaderType::BlinnPhongMirrored;
        f.dielectric |= s.type == ShaderType::Dielectric;
        // Conservative: roughness only matters on reflecting shaders, but switching gloss on for
        // a rough Lambertian costs a little speed, never a wrong image.
        // A Dielectric's roughness is translucency, not gloss: its kernel needs no gloss samples.
        f.gloss |= s.roughness > 0.0f && s.type != ShaderType::Dielectric;
        f.textures |= s.diffuseTexture != kNoTexture || s.specularTexture != kNoTexture;
        f.coolToWarm |= s.type == ShaderType::CoolToWarm;
        f.translucency |= s.type == ShaderType::Dielectric && s.roughness > 0.0f;
        f.diffuse |= s.diffuseBounce;
    }
    f.emitters = !scene.emitters.empty();
    f.environment = scene.environment.faceSize > 0 && options.environment;
    // The estimator matters only where a Diffuse surface meets emitters or the environment; other
    // scenes share one kernel whatever --estimator says.
    f.estimator = f.diffuse ? static_cast<std::uint32_t>(options.estimator) : gpu::ESTIMATOR_BOUNCE;
    f.maxDepth = (f.reflection || f.dielectric || f.diffuse) ? static_cast<std::uint32_t>(std::max(options.maxDepth, 0)) : 0u;
    f.pathStackSize = scenePathStack(f, options);
    // The one sampler the render uses: sample2D's other samplers would run too (every path runs
    // on lavapipe; host/gpu/README.md).
    f.sampler = static_cast<std::uint32_t>(options.sampler);
    f.thinLens = scene.cameras.at(options.camera).thinLens();
    return f;
}

FeatureSet generalFeatureSet(const RenderOptions& options, bool packedNodes) {
    FeatureSet f;  // every flag defaults to on
    f.packedNodes = packedNodes;
    f.maxDepth = static_cast<std::uint32_t>(std::max(options.maxDepth, 0));
    f.pathStackSize = pathStack(f.maxDepth, options);
    return f;
}

FeatureSet traversalFeatureSet(const bvh::SceneBvh& bvh, bool packedNodes) {
    FeatureSet f = geometryFeatures(bvh, packedNodes);
    f.areaLights = f.specular = f.reflection = f.gloss = f.dielectric = f.textures = f.coolToWarm = f.thinLens = f.translucency = false;
    f.diffuse = f.emitters = f.environment = false;
    f.estimator = gpu::ESTIMATOR_BOUNCE;
    f.maxDepth = 0;
    f.pathStackSize = 1;
    return f;
}

}  // namespace vkrt
