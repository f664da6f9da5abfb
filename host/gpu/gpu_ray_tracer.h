// Rays in, hits out on the GPU (shaders/trace_rays.comp): the same two-level traversal as the
// render kernel, for the ray-throughput benchmark and for testing traversal against the CPU's
// (bvh::intersectClosest / intersectAny). No Vulkan types in this header.
//
//   GpuRayTracer tracer(sceneBvh, {.validation = false});
//   std::vector<gpu::TraceHitOutput> hits = tracer.trace(rays, /*anyHit=*/false, &stats);
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "bvh.h"
#include "device_host.h"
#include "gpu_options.h"
#include "validation_log.h"

namespace vkrt {

struct GpuTraceStats {
    double pipelineSeconds = 0.0;  // creating the traversal kernel for this BVH (0 when cached)
    double traceSeconds = 0.0;     // the submissions alone, without ray upload and hit readback (wall clock)
    double kernelSeconds = -1.0;   // the same submissions by the device's timestamps; -1 without them
    std::uint32_t submissions = 0;
};

class GpuRayTracer {
public:
    // Uploads the BVH (checked against the device limits and the kernel's traversal stack).
    explicit GpuRayTracer(const bvh::SceneBvh& bvh, const GpuRendererOptions& options = {}, const GpuTestHooks& hooks = {});
    ~GpuRayTracer();
    GpuRayTracer(const GpuRayTracer&) = delete;
    GpuRayTracer& operator=(const GpuRayTracer&) = delete;

    // Closest hits (anyHit = false) or any hit with 0 < t < tMax (shadow rays). The hit of a
    // miss is 0xffffffff in x (TraceHitOutput). Rays go in batches of at most
    // maxRaysPerSubmission(), one submission each.
    std::vector<gpu::TraceHitOutput> trace(std::span<const gpu::TraceRayInput> rays, bool anyHit,
                                           GpuTraceStats* stats = nullptr);

    std::uint32_t maxRaysPerSubmission() const;
    std::string deviceName() const;
    // The node layout uploaded (node_packing.h): packed into 3 texels, and the boxes' area growth.
    bool packedNodes() const;
    double nodeAreaGrowth() const;
    std::shared_ptr<const ValidationLog> validationLog() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace vkrt
