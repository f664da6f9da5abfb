// The radiance of one camera sample: Whitted-style recursion with Cook's distribution effects and
// the course's path-traced Diffuse, written as a loop over an explicit stack of pending rays (GLSL
// has no recursion). Only dielectrics (two branches, in a scene without Diffuse surfaces: a
// path-traced scene's glass continues one) and depth-0 gloss samples push; everything else (a
// mirror's reflection, a Diffuse bounce) continues in place,
// so the stack never holds more than MAX_DEPTH + glossSamples entries (PATH_STACK_SIZE), and a
// scene with neither has no stack at all (PATH_STACK_SIZE = 0).
#ifndef VKRT_INTEGRATOR_GLSL
#define VKRT_INTEGRATOR_GLSL

const float MIN_RAY_WEIGHT = 1.0 / 1024.0;  // RENDERING.md §5: lighter rays are not traced

struct PathRay {
    vec3 origin;
    vec3 dir;      // unit length
    vec3 weight;
    uint depth;
    float bouncePdf;  // > 0: a Diffuse bounce of this cosine density whose surface's light samples
                      // already looked for emitters and the environment (the estimator weighs them)
};

// Children of the current hit: the first becomes the next ray, the rest wait on the stack.
struct PathQueue {
    PathRay next;
    bool hasNext;
    PathRay extra;  // a second child, until flushQueue pushes it
    bool hasExtra;
};

PathRay g_pathStack[PATH_STACK_ENTRIES];  // the megakernel's; the wavefront keeps each path's in memory
uint g_pathTop = 0u;

// Stack entry e: the megakernel's array, or the wavefront path's entries after its shadow rays
// (wavefront_state.glsl), which outlive the stage.
void storeStackEntry(uint e, PathRay r) {
    if (!WAVEFRONT) {
        g_pathStack[e] = r;
        return;
    }
    if (WAVEFRONT_STAGE == WAVEFRONT_SHADE_RECORD) return;  // SHADE_RESOLVE pushes the same rays
    uint field = WF_SHADOWS + 2u * wfShadowsPerPath() + 3u * e;
    wfStoreFloats(field, vec4(r.origin, uintBitsToFloat(r.depth)));
    wfStoreFloats(field + 1u, vec4(r.dir, r.bouncePdf));
    wfStoreFloats(field + 2u, vec4(r.weight, 0.0));
}

PathRay loadStackEntry(uint e) {
    if (!WAVEFRONT) return g_pathStack[e];
    uint field = WF_SHADOWS + 2u * wfShadowsPerPath() + 3u * e;
    vec4 a = wfLoadFloats(field);
    vec4 b = wfLoadFloats(field + 1u);
    return PathRay(a.xyz, b.xyz, wfLoadFloats(field + 2u).xyz, floatBitsToUint(a.w), b.w);
}

// Whether a child ray of a hit of this depth would end at the maximum depth where it can find no
// light (FINAL_*_DARK, host/lighting/final_rays.h): it is not traced, and the image is the same.
bool finalRayDark(uint depth, uint kind) {
    return depth + 1u >= frameMaxDepth() && (frameFinalRaysDark() & kind) != 0u;
}

// Records a child ray; a hit emits at most two between flushes (emitReflection flushes after each
// gloss sample).
void emitRay(inout PathQueue q, vec3 origin, vec3 dir, vec3 weight, uint depth, float bouncePdf) {
    if (max(max(weight.x, weight.y), weight.z) < MIN_RAY_WEIGHT) return;
    PathRay r = PathRay(origin, dir, weight, depth, bouncePdf);
    if (!q.hasNext) {
        q.next = r;
        q.hasNext = true;
    } else if (HAS_PATH_STACK) {
        q.extra = r;
        q.hasExtra = true;
    } else {
        g_rayStackOverflow = true;  // the host found no hit that emits two (feature_set.cpp)
    }
}

// The path stack's push, kept out of emitRay: lavapipe runs every push site on every path step
// for all lanes (a per-lane loop of masked stores of the 10-word ray), so one site in the path
// loop and one in the gloss loop instead of one per emitRay call. The stack receives the same
// rays in the same order as when emitRay pushed.
void flushQueue(inout PathQueue q) {
    if (!HAS_PATH_STACK || !q.hasExtra) return;
    if (g_pathTop < PATH_STACK_SIZE) {
        storeStackEntry(g_pathTop++, q.extra);
    } else {
        g_rayStackOverflow = true;  // reported once by render.comp (see traverse.glsl)
    }
    q.hasExtra = false;
}

// The mirror direction perturbed within the square of side `roughness` in r's (U, V) basis.
vec3 glossyDirection(vec3 r, float roughness, vec2 u) {
    vec3 a = abs(r);
    vec3 axis = (a.x <= a.y && a.x <= a.z) ? vec3(1.0, 0.0, 0.0) : (a.y <= a.z ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    vec3 U = normalize(cross(r, axis));
    vec3 V = cross(r, U);
    if (roughness > 1.0) {
        // Divided by the roughness (same direction): r + a*(..) overflowed for a > ~1e19 and every
        // sample came out black; rescaled by the largest component since r / a can be tiny.
        vec3 w = r / roughness + (u.x - 0.5) * U + (u.y - 0.5) * V;
        float m = max(max(abs(w.x), abs(w.y)), abs(w.z));
        return m > 0.0 ? normalize(w / m) : r;
    }
    return normalize(r + roughness * (u.x - 0.5) * U + roughness * (u.y - 0.5) * V);
}

// Reflection rays of a reflective material (mirror direction, or glossy samples of it).
void emitReflection(inout PathQueue q, PathRay ray, Surface s, vec3 N, float roughness, vec3 weight, SampleKey key) {
    if (ray.depth >= MAX_DEPTH || ray.depth >= frameMaxDepth() || finalRayDark(ray.depth, FINAL_REFLECTION_DARK)) return;
    vec3 r = reflect(ray.dir, N);
    if (!HAS_GLOSS || roughness <= 0.0) {
        if (dot(r, s.geomNormal) > 0.0) emitRay(q, offsetTowards(s, r), r, weight, ray.depth + 1u, 0.0);
        return;
    }
    bool fanOut = ray.depth == 0u;  // gloss samples apply at primary hits only (RENDERING.md §5)
    uint g = fanOut ? frameGlossSamples() : 1u;
    vec3 w = weight / float(g);
    uint j = 0u;
    for (; j < g; ++j) {
        if (!chargeLoop()) break;
        vec2 u = fanOut ? sample2D(samplerKind(), frame.glossGrid, key.pixel, key.index * g + j, dimGloss(0u), key.seed)
                        : sample2D(samplerKind(), frame.pixelGrid, key.pixel, key.index, dimGloss(ray.depth), key.seed);
        vec3 rg = glossyDirection(r, roughness, u);
        if (dot(rg, s.geomNormal) > 0.0) emitRay(q, offsetTowards(s, rg), rg, w, ray.depth + 1u, 0.0);
        flushQueue(q);
    }
    if (j < g) markLoopCutOff();
}

// Fresnel-weighted reflection and refraction at a dielectric boundary (RENDERING.md §6).
void emitDielectric(inout PathQueue q, PathRay ray, Surface s, Material m, float hitDistance, SampleKey key) {
    bool entering = dot(ray.dir, s.geomNormal) < 0.0;
    vec3 weight = ray.weight;
    // Leaving the medium: Beer-Lambert over the distance travelled inside (per-unit transmittance).
    if (!entering) weight *= pow(max(m.attenuation.rgb, vec3(0.0)), vec3(hitDistance));
    if (ray.depth >= MAX_DEPTH || ray.depth >= frameMaxDepth() || finalRayDark(ray.depth, FINAL_REFLECTION_DARK)) return;
    float eta = materialRefractiveIndex(m);
    vec3 n = entering ? s.shadeNormal : -s.shadeNormal;  // faces the incoming ray
    float n1 = entering ? 1.0 : eta;
    float n2 = entering ? eta : 1.0;
    float cosI = clamp(-dot(ray.dir, n), 0.0, 1.0);
    float F;
    vec3 refracted = ray.dir;
    if (eta == 1.0) {
        F = 0.0;  // index-matched: no reflection, no bending (exactly)
    } else {
        float ratio = n1 / n2;
        float sin2T = ratio * ratio * (1.0 - cosI * cosI);
        if (sin2T >= 1.0) {
            F = 1.0;  // total internal reflection
        } else {
            float cosT = sqrt(1.0 - sin2T);
            float rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
            float rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
            F = 0.5 * (rs * rs + rp * rp);
            refracted = normalize(ratio * ray.dir + (ratio * cosI - cosT) * n);
        }
    }
    // A path-traced scene continues one branch, reflection with probability F, each carrying the
    // whole weight (F / F): the same expectation as both branches, at the cost of one path.
    bool reflects = F > 0.0, refracts = F < 1.0;
    vec3 reflectedWeight = weight * F, refractedWeight = weight * (1.0 - F);
    if (HAS_DIFFUSE && frameDielectricOneBranch() && reflects && refracts) {
        reflects = sample1D(samplerKind(), frame.pixelGrid, key.pixel, key.index, dimRoulette(ray.depth), key.seed) < F;
        refracts = !reflects;
        reflectedWeight = refractedWeight = weight;
    }
    if (reflects) {
        vec3 r = reflect(ray.dir, n);
        emitRay(q, offsetTowards(s, r), r, reflectedWeight, ray.depth + 1u, 0.0);
    }
    if (refracts) {
        float roughness = materialRoughness(m);
        if (HAS_TRANSLUCENCY && roughness > 0.0) {
            // Glossy translucency: the refracted direction perturbed in its (U, V) basis, one
            // direction per pixel sample; one that leaves on the incoming side carries no light.
            vec2 u = sample2D(samplerKind(), frame.pixelGrid, key.pixel, key.index, dimTranslucency(ray.depth), key.seed);
            refracted = glossyDirection(refracted, roughness, u);
            if (dot(refracted, n) >= 0.0) return;
        }
        emitRay(q, offsetTowards(s, refracted), refracted, refractedWeight, ray.depth + 1u, 0.0);
    }
}

// The Diffuse bounce (RENDERING.md §5): one cosine-weighted direction per pixel sample, carrying
// kd (f cos / pdf = (kd / pi) cos / (cos / pi)); none below the geometric surface.
void emitBounce(inout PathQueue q, PathRay ray, Surface s, vec3 N, vec3 kd, SampleKey key) {
    if (finalRayDark(ray.depth, FINAL_BOUNCE_DARK)) return;
    vec2 u = sample2D(samplerKind(), frame.pixelGrid, key.pixel, key.index, dimBounce(ray.depth), key.seed);
    vec3 dir = cosineDirection(N, u);
    if (dot(dir, s.geomNormal) <= 0.0) return;
    // Russian roulette where the path's weight has fallen below its depth's threshold (RENDERING.md §5).
    vec3 weight = ray.weight * kd;
    float m = max(max(weight.x, weight.y), weight.z);
    float threshold = rouletteThreshold(ray.depth);
    if (m < threshold) {
        float factor = rouletteFactor(m, threshold, sample1D(samplerKind(), frame.pixelGrid, key.pixel, key.index, dimRoulette(ray.depth), key.seed));
        if (!(factor > 0.0)) return;
        weight *= factor;
    }
    float pdf = estimatorKind() != ESTIMATOR_BOUNCE ? max(cosinePdf(N, dir), 1e-30) : 0.0;
    emitRay(q, offsetTowards(s, dir), dir, weight, ray.depth + 1u, pdf);
}

// What a ray sees on an emitter's surface: its radiance, weighted against the light samples of
// the Diffuse surface the ray left, if it left one that took them.
vec3 emittedRadiance(PathRay ray, Surface s, Material m) {
    vec3 L = m.diffuse.rgb;
    if (!(ray.bouncePdf > 0.0)) return L;
    uint estimator = estimatorKind();
    if (estimator == ESTIMATOR_NEE) return vec3(0.0);  // next-event estimation counted it already
    EmitterRecord e = loadEmitter(materialEmitter(m));
    float lightPdf = float(frameLightSamples()) * emitterChoicePdf(e) * emitterPdf(e, ray.origin, s.position, s.geomNormal);
    return L * misWeight(ray.bouncePdf, lightPdf, estimator == ESTIMATOR_MIS_POWER);
}

// One ray of a camera sample's tree, given its closest hit (`found` false: it left the scene):
// the light it brings adds to `radiance`, its children go to q. The megakernel's path loop below
// and the wavefront's shading stages (wavefront.glsl) share it.
void shadeRay(PathRay ray, bool found, Hit hit, SampleKey key, inout vec3 radiance, inout PathQueue q) {
    if (!found) {
        // The general kernel has HAS_ENVIRONMENT for every scene: a face size of 0 says none.
        bool mapped = HAS_ENVIRONMENT && frameEnvironmentFaceSize() > 0u;
        radiance += ray.weight * (mapped ? escapedRadiance(ray.dir, ray.bouncePdf) : frame.background.rgb);
    } else {
        Surface s = surfaceAt(ray.origin, ray.dir, hit);
        Material m = loadMaterial(s.material);
        uint type = materialType(m);
        if (HAS_EMITTERS && type == SHADER_EMITTER) {
            radiance += ray.weight * emittedRadiance(ray, s, m);
        } else if (HAS_DIELECTRIC && type == SHADER_DIELECTRIC) {
            emitDielectric(q, ray, s, m, hit.t, key);
        } else {
            // Two-sided shading: turn the normals towards the viewer.
            vec3 V = -ray.dir;
            if (dot(s.geomNormal, V) < 0.0) {
                s.geomNormal = -s.geomNormal;
                s.shadeNormal = -s.shadeNormal;
            }
            vec3 N = s.shadeNormal;
            vec3 kd = m.diffuse.rgb;
            vec3 ks = m.specular.rgb;
            if (HAS_TEXTURES) {
                uint diffuseTexture = materialDiffuseTexture(m);
                uint specularTexture = materialSpecularTexture(m);
                if (diffuseTexture != TEXTURE_NONE) kd *= sampleTexture(diffuseTexture, s.uv);
                if (specularTexture != TEXTURE_NONE) ks *= sampleTexture(specularTexture, s.uv);
            }
            // A Diffuse surface reflects nothing at the maximum depth: every light it reflects,
            // its direct light included, is a bounce (RENDERING.md §5).
            bool diffuseSurface = HAS_DIFFUSE && type == SHADER_DIFFUSE;
            bool bounces = diffuseSurface && ray.depth < MAX_DEPTH && ray.depth < frameMaxDepth();
            vec3 local = vec3(0.0);
            if (type != SHADER_MIRROR && (!diffuseSurface || bounces)) {
                local = directLighting(s, N, V, type, kd, ks, materialPhongExponent(m), ray.depth, key);
                if (HAS_ENVIRONMENT && bounces && frameEnvironmentFaceSize() > 0u)
                    local += environmentLighting(s, N, kd, ray.depth, key);
            }
            // The shares of local shading and of reflection: mirror 0 and 1, glaze 1 and m,
            // mirrored Blinn-Phong 1 - m and m, the others 1 and none (RENDERING.md §5). One
            // emitReflection call for the three reflecting shaders, not one each: lavapipe runs
            // every inlined copy of its gloss loop on every path step, whatever the shader.
            float mirror = materialMirrorCoef(m);
            bool reflects = HAS_REFLECTION && (type == SHADER_MIRROR || type == SHADER_GLAZE ||
                                               type == SHADER_BLINN_PHONG_MIRRORED);
            float localShare = !reflects || type == SHADER_GLAZE ? 1.0 : (type == SHADER_MIRROR ? 0.0 : 1.0 - mirror);
            radiance += ray.weight * localShare * local;
            if (reflects)
                emitReflection(q, ray, s, N, materialRoughness(m), ray.weight * (type == SHADER_MIRROR ? 1.0 : mirror), key);
            if (bounces) emitBounce(q, ray, s, N, kd, key);
        }
    }
}

vec3 cameraSampleRadiance(vec3 origin, vec3 dir, SampleKey key) {
    vec3 radiance = vec3(0.0);
    g_pathTop = 0u;
    PathRay ray = PathRay(origin, dir, vec3(1.0), 0u, 0.0);
    bool finished = false;  // set by the loop's own exit (budget.glsl)
    while (true) {
        if (!chargeLoop()) break;
        PathQueue q;
        q.hasNext = false;
        q.hasExtra = false;
        Hit hit;
        bool found = traceScene(ray.origin, ray.dir, FLT_MAX, false, hit);
        shadeRay(ray, found, hit, key, radiance, q);
        flushQueue(q);
        if (g_budgetExceeded) break;
        if (q.hasNext) {
            ray = q.next;
        } else if (HAS_PATH_STACK && g_pathTop > 0u) {
            ray = loadStackEntry(--g_pathTop);
        } else {
            finished = true;
            break;
        }
    }
    if (!finished) markLoopCutOff();
    return radiance;
}

#endif
