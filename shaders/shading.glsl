// Local shading: every light (and area-light sample) with its shadow ray, per the material's
// model (docs/RENDERING.md §4, §5).
#ifndef VKRT_SHADING_GLSL
#define VKRT_SHADING_GLSL

// Where a sample is in the sampling sequence (sampling.h keys).
struct SampleKey {
    uint pixel;
    uint index;   // pixel sample s
    uint seed;
};

// A shadow ray ends just short of the light (RENDERING.md §4): t is in units of (q - origin).
const float SHADOW_T_MAX = 1.0 - 1.0 / 65536.0;

bool visible(Surface s, vec3 towardsLight, vec3 lightPoint) {
    vec3 origin = offsetTowards(s, towardsLight);
    return shadowRayClear(origin, lightPoint - origin, SHADOW_T_MAX);
}

// Shading of one light position q with intensity I. N faces the viewer.
vec3 lightFrom(Surface s, vec3 N, vec3 V, uint type, vec3 kd, vec3 ks, float phongExp, vec3 q, vec3 I) {
    vec3 toLight = q - s.position;
    float dist2 = dot(toLight, toLight);
    if (!(dist2 > 0.0)) return vec3(0.0);
    vec3 L = toLight * inversesqrt(dist2);
    float nDotL = dot(N, L);
    if (HAS_COOL_TO_WARM && type == SHADER_COOL_TO_WARM) {
        // Gooch et al. 1998: blend from cool (facing away) to warm (facing the light); unshadowed.
        vec3 kCool = vec3(0.0, 0.0, 0.4) + 0.2 * kd;
        vec3 kWarm = vec3(0.4, 0.4, 0.0) + 0.6 * kd;
        float t = 0.5 * (1.0 + nDotL);
        return I * (t * kWarm + (1.0 - t) * kCool);
    }
    if (nDotL <= 0.0) return vec3(0.0);
    if (!visible(s, L, q)) return vec3(0.0);
    vec3 c = kd * nDotL;
    if (HAS_SPECULAR && (type == SHADER_BLINN_PHONG || type == SHADER_BLINN_PHONG_MIRRORED)) {
        // L = -V leaves the half vector undefined: no highlight (as the CPU reference does).
        vec3 H = normalizeOr(L + V, vec3(0.0));
        float nDotH = max(dot(N, H), 0.0);
        // pow(0, 0) is undefined in GLSL; the course's exponent 0 means a constant highlight of 1.
        if (dot(H, H) > 0.0) c += ks * (phongExp == 0.0 ? 1.0 : pow(nDotH, phongExp));
    }
    return c * I;
}

// Shape emitters as a continuum of the course's point lights (RENDERING.md §4): a light sample of
// density p (per steradian) stands for intensity L / (pi p). Each of the k light samples goes to
// one emitter, chosen by its share of the emitters' power (p includes that share). A Diffuse
// surface samples them only as the estimator says, weighted against its bounce.
vec3 emitterLighting(Surface s, vec3 N, vec3 V, uint type, vec3 kd, vec3 ks, float phongExp, uint depth, SampleKey key) {
    bool diffuseSurface = HAS_DIFFUSE && type == SHADER_DIFFUSE;
    uint estimator = estimatorKind();
    if (diffuseSurface && estimator == ESTIMATOR_BOUNCE) return vec3(0.0);
    bool weighs = diffuseSurface && (estimator == ESTIMATOR_MIS_BALANCE || estimator == ESTIMATOR_MIS_POWER);
    uint count = frameEmitterCount();
    uint k = frameLightSamples();
    if (count == 0u) return vec3(0.0);
    vec3 sum = vec3(0.0);
    uint j = 0u;
    for (; j < k; ++j) {
        if (!chargeLoop()) break;
        uint e = count == 1u ? 0u
                             : pickEmitter(count, sample1D(samplerKind(), frame.lightGrid, key.pixel, key.index * k + j,
                                                           dimEmitterChoice(depth), key.seed));
        EmitterRecord r = loadEmitter(e);
        vec2 u = sample2D(samplerKind(), frame.lightGrid, key.pixel, key.index * k + j,
                          dimLight(depth, emitterLightOrdinal(r)), key.seed);
        EmitterSample es = sampleEmitter(r, s.position, u);
        float pdf = emitterChoicePdf(r) * es.pdf;
        if (!(pdf > 0.0) || isinf(pdf)) continue;
        float w = 1.0;
        if (weighs) {
            // The bounce reaches this direction with its cosine density, or not at all below
            // the geometric surface (emitBounce does not trace those).
            vec3 l = normalize(es.point - s.position);
            float bouncePdf = dot(l, s.geomNormal) > 0.0 ? cosinePdf(N, l) : 0.0;
            w = misWeight(float(k) * pdf, bouncePdf, estimator == ESTIMATOR_MIS_POWER);
        }
        if (w > 0.0) sum += lightFrom(s, N, V, type, kd, ks, phongExp, es.point, r.radiance.rgb * (w * EMITTER_INV_PI / pdf));
    }
    if (j < k) markLoopCutOff();
    return sum / float(k);
}

vec3 directLighting(Surface s, vec3 N, vec3 V, uint type, vec3 kd, vec3 ks, float phongExp, uint depth, SampleKey key) {
    vec3 sum = vec3(0.0);
    uint lightCount = frameLightCount();
    uint l = 0u;
    for (; l < lightCount; ++l) {
        if (!chargeLoop()) break;
        Light light = loadLight(l);
        // Point and area lights share one sample loop (a point light: one sample at its position)
        // so the shadow-ray traversal is inlined once here, not twice: a smaller kernel, and a
        // faster one on lavapipe (docs/lab/2026-12-02-lavapipe-kernel.md).
        bool area = HAS_AREA_LIGHTS && lightType(light) == LIGHT_AREA;
        uint k = area ? frameLightSamples() : 1u;
        vec3 acc = vec3(0.0);
        uint j = 0u;
        for (; j < k; ++j) {
            if (!chargeLoop()) break;
            vec3 q = light.position.xyz;
            if (area) {
                vec2 u = sample2D(samplerKind(), frame.lightGrid, key.pixel, key.index * k + j,
                                  dimLight(depth, lightAreaOrdinal(light)), key.seed);
                q += (u.x - 0.5) * light.edgeU.xyz + (u.y - 0.5) * light.edgeV.xyz;
            }
            acc += lightFrom(s, N, V, type, kd, ks, phongExp, q, light.intensity.rgb);
        }
        if (j < k) markLoopCutOff();
        sum += acc / float(k);  // exact for a point light (k = 1)
    }
    if (l < lightCount) markLoopCutOff();
    if (HAS_EMITTERS) sum += emitterLighting(s, N, V, type, kd, ks, phongExp, depth, key);
    return sum;
}

#endif
