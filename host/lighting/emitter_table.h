// Scene::emitters -> the records both renderers sample them by (gpu::EmitterRecord and
// gpu::EmitterTriangle, shaders/shared/device_host.h; the sampling itself is
// shaders/shared/emitter_sampling.h). World space, in Scene::emitters order.
#pragma once

#include <cstdint>
#include <vector>

#include "device_host.h"
#include "emitter_sampling.h"
#include "scene.h"

namespace vkrt {

struct EmitterTable {
    std::vector<gpu::EmitterRecord> records;     // one per Scene::emitters entry
    std::vector<gpu::EmitterTriangle> triangles; // the EMITTER_TRIANGLES records' triangles
};

// The number of area lights: the emitters' light ordinals (sampling dimensions) follow theirs.
std::uint32_t areaLightCount(const Scene& scene);

// A sphere stays a sphere (sampled by its cone) under a similarity; any other affine map makes it
// an ellipsoid (sampled by area). Boxes are their twelve triangles, wound outwards and marked
// convex (choice.z: light samples go to the faces in front of the point), meshes their triangles. Each
// record's choice share is its estimated power (mean radiance of r, g, b times area) over the
// emitters' total: the emitter a light sample goes to (docs/RENDERING.md §4).
EmitterTable buildEmitterTable(const Scene& scene);

// The emitter a light sample u in [0, 1) goes to: the first whose cumulative choice share exceeds
// u (the GLSL kernel's pickEmitter is the same search).
std::uint32_t pickEmitter(const EmitterTable& table, float u);

// The index of the triangle an EMITTER_TRIANGLES sample u.x picks: the first whose cumulative
// share exceeds u (the GLSL kernel's search is the same: the same triangle on both devices).
std::uint32_t pickEmitterTriangle(const EmitterTable& table, const gpu::EmitterRecord& record, float u);

// A point of `record` seen from x for the 2D light sample u, by its kind's rule (emitter_sampling.h;
// the kernel's sampleEmitter in shaders/emitters.glsl is the same dispatch). pdf 0: no point.
emitters::EmitterSample sampleEmitter(const EmitterTable& table, const gpu::EmitterRecord& record, const glm::vec3& x,
                                      glm::vec2 u);
// The solid-angle density at x with which sampleEmitter reaches the record's point q (normal nq).
float emitterPdf(const EmitterTable& table, const gpu::EmitterRecord& record, const glm::vec3& x, const glm::vec3& q,
                 const glm::vec3& nq);

}  // namespace vkrt
