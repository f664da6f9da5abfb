// `vkrt-bench gpu rays MESH.obj|sphere:N [W H SPP]`: the Embree peer's primary, shadow and diffuse
// rays (peer_rays.h, the same streams `vkrt-bench bvh` traces) traced on the GPU through
// GpuRayTracer (shaders/trace_rays.comp), then, in the same round, the same ray arrays on the CPU
// traversal and the peer on the same input, so the ratios GPU/CPU and GPU/Embree come from figures
// taken together (this machine's speed drifts by +-50% minute to minute). The secondary rays start
// from the CPU's primary hits, so both devices trace identical arrays and every GPU hit can be
// checked against the CPU's: a broken kernel shows up as mismatches, not as a fast figure.
// GPU rates are given twice: by wall clock around submit and fence, and by the device's own
// timestamps (kernel_Mrays_per_s), which a fast GPU needs: there a submission's latency is a large
// part of its wall time. --zoom Z narrows the view so the mesh fills the frame (the peer's camera
// misses with ~90% of its rays on the dragon; the Embree peer is then not run, its rays would differ).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_args.h"
#include "bench_gpu.h"
#include "bench_mesh.h"
#include "bench_timing.h"
#include "gpu_build_options.h"
#include "gpu_ray_tracer.h"
#include "peer_rays.h"
#include "peer_runner.h"

namespace vkrt::bench {

namespace {

// The targets for GPU throughput against Embree (same rays, same machine).
constexpr double kPrimaryTarget = 0.7, kShadowTarget = 0.45;
// Where ../shared/peer/README.md builds the peer by default.
constexpr const char* kDefaultPeer = "/tmp/embree_peer";
constexpr std::uint32_t kMiss = 0xffffffffu;

struct Args {
    std::string source;
    int width = 512, height = 512, spp = 4;
    int threads = 2;  // CPU traversal and Embree; lavapipe uses every core (LP_NUM_THREADS)
    int rounds = 5;
    double zoom = 1.0;  // > 1 narrows the peer's view onto the mesh's centre (PeerCamera::halfExtent)
    std::string peer;
    std::string shaderDir;  // kernel GLSL compiled at run time (shader developers' A/B runs)
    bool buildPeer = false, noPeer = false;
    // GPU and CPU traversal share algorithms, not arithmetic (the device may fuse multiply-adds),
    // so grazing rays may go either way; tests/vulkan/test_ray_tracer.cpp allows 0.2%.
    double maxMismatchFraction = 0.002;
    // The GPU kernel's tree (--ctrav, --cisect, --max-leaf: its SAH constants, for measuring them);
    // the CPU traces its own tree, built with the CPU's constants, as each renderer would.
    bvh::BuildOptions build = gpuBuildOptions();
};

Args parseArgs(const std::vector<std::string>& args) {
    Args a;
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const bool value = i + 1 < args.size();
        if (args[i] == "--peer" && value) a.peer = args[++i];
        else if (args[i] == "--build-peer") a.buildPeer = true;
        else if (args[i] == "--shader-dir" && value) a.shaderDir = args[++i];
        else if (args[i] == "--no-peer") a.noPeer = true;
        else if (args[i] == "--rounds" && value) a.rounds = positiveInt(args[++i], "--rounds");
        else if (args[i] == "--zoom" && value) a.zoom = nonNegativeNumber(args[++i], "--zoom");
        else if (args[i] == "--threads" && value) a.threads = positiveInt(args[++i], "--threads");
        else if (args[i] == "--max-mismatch-fraction" && value)
            a.maxMismatchFraction = nonNegativeNumber(args[++i], "--max-mismatch-fraction");
        else if (args[i] == "--ctrav" && value) a.build.traversalCost = nonNegativeNumber(args[++i], "--ctrav");
        else if (args[i] == "--cisect" && value) a.build.intersectionCost = nonNegativeNumber(args[++i], "--cisect");
        else if (args[i] == "--max-leaf" && value) a.build.maxLeafSize = positiveInt(args[++i], "--max-leaf");
        else if (args[i].rfind("--", 0) == 0) throw std::runtime_error("unknown option " + args[i]);
        else positional.push_back(args[i]);
    }
    if (positional.empty() || positional.size() > 4)
        throw std::runtime_error("usage: vkrt-bench gpu rays MESH.obj|sphere:N [W H SPP] [--rounds R] [--threads T] "
                                 "[--zoom Z] [--peer PATH | --build-peer | --no-peer] [--max-mismatch-fraction F] [--shader-dir DIR] "
                                 "[--ctrav C] [--cisect C] [--max-leaf N]");
    a.source = positional[0];
    if (positional.size() > 1) a.width = positiveInt(positional[1], "W");
    if (positional.size() > 2) a.height = positiveInt(positional[2], "H");
    if (positional.size() > 3) a.spp = positiveInt(positional[3], "SPP");
    return a;
}

// --peer, $VKRT_EMBREE_PEER or --build-peer as `vkrt-bench bvh`; failing those, the peer's
// documented default place, so a peer built once is used without flags.
std::string findPeer(const Args& a) {
    if (a.noPeer || a.zoom != 1.0) return "";  // the peer has no zoom: its rays would not be these
    const std::string peer = locatePeer(a.peer, a.buildPeer);
    if (!peer.empty() || !a.peer.empty()) return peer;
    return locatePeer(kDefaultPeer, false);
}

enum class Kind { Primary, Shadow, Diffuse };
constexpr Kind kKinds[] = {Kind::Primary, Kind::Shadow, Kind::Diffuse};
const char* name(Kind k) { return k == Kind::Primary ? "primary" : k == Kind::Shadow ? "shadow" : "diffuse"; }
bool anyHit(Kind k) { return k == Kind::Shadow; }

// A traced ray's outcome in the GPU's encoding (TraceHitOutput), so both sides compare directly.
struct Outcome {
    std::uint32_t prim = kMiss;  // kMiss for a miss
    float t = 0.0f;              // closest hits only
};

struct RaySet {
    std::vector<bvh::Ray> cpu;
    std::vector<gpu::TraceRayInput> gpu;
    std::vector<Outcome> reference;  // the CPU's outcome, for the mismatch count

    void add(const bvh::Ray& r) {
        cpu.push_back(r);
        gpu.push_back({glm::vec4(r.origin, r.tmax), glm::vec4(r.dir, 0.0f)});
    }
};

// Traces `rays` on the CPU over `threads` threads in chunks (rays, not rows: the secondary sets
// are compacted), writing each outcome. Seconds of the traversal alone.
double traceCpu(const bvh::SceneBvh& scene, const std::vector<bvh::Ray>& rays, bool any, int threads,
                std::vector<Outcome>& out) {
    constexpr std::size_t kChunk = 1024;
    out.assign(rays.size(), {});
    const int chunks = static_cast<int>((rays.size() + kChunk - 1) / kChunk);
    return overItems(chunks, threads, [&](int c) {
        const std::size_t end = std::min(rays.size(), (c + 1) * kChunk);
        for (std::size_t i = c * kChunk; i < end; ++i) {
            if (any) {
                if (bvh::intersectAny(scene, rays[i])) out[i].prim = 0;
            } else if (bvh::Hit h; bvh::intersectClosest(scene, rays[i], h)) {
                out[i] = {h.prim, h.t};
            }
        }
    });
}

// The three sets: primary rays of the whole image, then one shadow and one diffuse ray per CPU
// primary hit, in the peer's order and random streams.
std::vector<RaySet> makeRays(const bvh::SceneBvh& scene, const PeerCamera& cam, const Args& a) {
    std::vector<RaySet> sets(3);
    RaySet& primary = sets[0];
    const std::size_t n = static_cast<std::size_t>(a.width) * a.height * a.spp;
    primary.cpu.resize(n);
    for (int y = 0; y < a.height; ++y)
        forEachPrimaryRay(cam, a.width, a.height, a.spp, y, [&](std::size_t k, const bvh::Ray& r) { primary.cpu[k] = r; });
    for (const bvh::Ray& r : primary.cpu) primary.gpu.push_back({glm::vec4(r.origin, r.tmax), glm::vec4(r.dir, 0.0f)});
    traceCpu(scene, primary.cpu, false, a.threads, primary.reference);

    const std::size_t perRow = static_cast<std::size_t>(a.width) * a.spp;
    for (int y = 0; y < a.height; ++y) {
        DiffuseRow row(y);
        for (std::size_t k = y * perRow; k < (y + 1) * perRow; ++k) {
            const Outcome& hit = primary.reference[k];
            if (hit.prim == kMiss) continue;
            const glm::vec3 p = primary.cpu[k].origin + primary.cpu[k].dir * hit.t;
            const glm::vec3 nrm = facingNormal(scene.prims[hit.prim], primary.cpu[k].dir);
            sets[1].add(shadowRay(cam, p, nrm));
            sets[2].add(row.next(cam, p, nrm));
        }
    }
    traceCpu(scene, sets[1].cpu, true, a.threads, sets[1].reference);
    traceCpu(scene, sets[2].cpu, false, a.threads, sets[2].reference);
    return sets;
}

// The two trees order the primitives differently: a hit is compared by the mesh triangle it
// names (SceneBvh::primSource), not by its place in either array.
std::size_t mismatches(const bvh::SceneBvh& cpuScene, const std::vector<Outcome>& cpu, const bvh::SceneBvh& gpuScene,
                       const std::vector<gpu::TraceHitOutput>& gpu, bool any) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < cpu.size(); ++i) {
        const bool gpuHit = gpu::traceHitTBits(gpu[i]) != kMiss, cpuHit = cpu[i].prim != kMiss;
        if (gpuHit != cpuHit ||
            (!any && gpuHit && gpuScene.primSource[gpu::traceHitPrimitive(gpu[i])] != cpuScene.primSource[cpu[i].prim]))
            ++count;
    }
    return count;
}

// Per kind: GPU (wall clock and, where the queue has timestamps, device time), CPU and Embree
// rates (Mrays/s) of every round, and the per-round ratios.
struct Series {
    std::vector<double> gpu, gpuKernel, cpu, embree, gpuOverCpu, gpuOverEmbree;
};

double embreeRate(const PeerFigures& f, Kind k) {
    return k == Kind::Primary ? f.primaryMrays : k == Kind::Shadow ? f.shadowMrays : f.diffuseMrays;
}

}  // namespace

int runGpuRaysBench(const std::vector<std::string>& argv) {
    const Args a = parseArgs(argv);
    const BenchMesh mesh = loadBenchMesh(a.source);
    if (a.zoom <= 0.0) throw std::runtime_error("--zoom must be above 0");
    PeerCamera cam(mesh);
    cam.halfExtent = static_cast<float>(0.8 / a.zoom);
    const std::string peer = findPeer(a);
    if (peer.empty())
        std::fprintf(stderr, "no Embree peer (--peer PATH, $VKRT_EMBREE_PEER, --build-peer or %s): GPU and CPU only\n",
                     kDefaultPeer);

    const std::vector<std::vector<bvh::PrimitiveInput>> groups = {toPrimitives(mesh)};
    const std::vector<bvh::InstanceInput> instances = {{0, glm::mat4(1.0f), gpu::MATERIAL_NONE}};
    bvh::BuildOptions cpuBuild;
    cpuBuild.threads = a.threads;
    const bvh::SceneBvh scene = bvh::buildSceneBvh(groups, instances, cpuBuild);
    bvh::BuildOptions gpuBuild = a.build;
    gpuBuild.threads = a.threads;
    const bvh::SceneBvh gpuScene = bvh::buildSceneBvh(groups, instances, gpuBuild);
    const std::vector<RaySet> sets = makeRays(scene, cam, a);

    const auto uploadStart = std::chrono::steady_clock::now();
    GpuRendererOptions gpuOptions;
    if (!a.shaderDir.empty()) gpuOptions.shaderDir = a.shaderDir;
    GpuRayTracer tracer(gpuScene, gpuOptions);
    const double uploadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - uploadStart).count();

    // Warm-up: creates the pipeline and lets lavapipe JIT it at its first dispatch; its hits are
    // the ones checked (the kernel is deterministic, the timed rounds trace the same arrays).
    std::vector<std::size_t> wrong(3);
    GpuTraceStats warmUp;
    double warmUpSeconds = 0.0;
    for (Kind k : kKinds) {
        const RaySet& set = sets[static_cast<int>(k)];
        const auto hits = tracer.trace(set.gpu, anyHit(k), &warmUp);
        warmUpSeconds += warmUp.pipelineSeconds + warmUp.traceSeconds;
        wrong[static_cast<int>(k)] = mismatches(scene, set.reference, gpuScene, hits, anyHit(k));
    }

    std::vector<Series> series(3);
    std::vector<Outcome> scratch;
    std::size_t peerShadowRays = 0;
    for (int round = 0; round < a.rounds; ++round) {
        std::vector<double> gpuRate(3), kernelRate(3, -1.0), cpuRate(3);
        for (Kind k : kKinds) {
            const RaySet& set = sets[static_cast<int>(k)];
            GpuTraceStats stats;
            tracer.trace(set.gpu, anyHit(k), &stats);
            gpuRate[static_cast<int>(k)] = set.gpu.size() / stats.traceSeconds / 1e6;
            if (stats.kernelSeconds > 0.0) kernelRate[static_cast<int>(k)] = set.gpu.size() / stats.kernelSeconds / 1e6;
        }
        for (Kind k : kKinds) {
            const RaySet& set = sets[static_cast<int>(k)];
            cpuRate[static_cast<int>(k)] = set.cpu.size() / traceCpu(scene, set.cpu, anyHit(k), a.threads, scratch) / 1e6;
        }
        std::optional<PeerFigures> embree;
        if (!peer.empty()) embree = runPeer(peer, a.source, a.width, a.height, a.spp, a.threads, "high");
        if (embree) peerShadowRays = embree->shadowRays;
        std::fprintf(stderr, "round %d Mrays/s:", round + 1);
        for (Kind k : kKinds) {
            const int i = static_cast<int>(k);
            Series& s = series[i];
            s.gpu.push_back(gpuRate[i]);
            if (kernelRate[i] > 0.0) s.gpuKernel.push_back(kernelRate[i]);
            s.cpu.push_back(cpuRate[i]);
            s.gpuOverCpu.push_back(gpuRate[i] / cpuRate[i]);
            if (embree) {
                s.embree.push_back(embreeRate(*embree, k));
                s.gpuOverEmbree.push_back(gpuRate[i] / embreeRate(*embree, k));
            }
            std::fprintf(stderr, "  %s gpu %.2f cpu %.2f", name(k), gpuRate[i], cpuRate[i]);
            if (embree) std::fprintf(stderr, " embree %.2f", embreeRate(*embree, k));
        }
        std::fprintf(stderr, "\n");
    }

    std::printf("device %s triangles %zu upload_s %.3f warmup_s %.3f nodes %s area_growth %.6f\n", tracer.deviceName().c_str(),
                mesh.triangles.size(), uploadSeconds, warmUpSeconds, tracer.packedNodes() ? "packed" : "exact",
                tracer.nodeAreaGrowth());
    std::printf("trees gpu ctrav %.2f cisect %.2f nodes %zu cpu ctrav %.2f cisect %.2f nodes %zu\n", gpuBuild.traversalCost,
                gpuBuild.intersectionCost, gpuScene.nodes.size(), cpuBuild.traversalCost, cpuBuild.intersectionCost,
                scene.nodes.size());
    std::printf("camera zoom %.2f primary_hit_fraction %.3f\n", a.zoom,
                static_cast<double>(sets[1].gpu.size()) / static_cast<double>(sets[0].gpu.size()));
    for (Kind k : kKinds) {  // the peer's line format, GPU figures: wall clock, then device timestamps
        const Series& s = series[static_cast<int>(k)];
        std::printf("%s rays %zu Mrays_per_s %.2f", name(k), sets[static_cast<int>(k)].gpu.size(), median(s.gpu));
        if (s.gpuKernel.size() == s.gpu.size() && !s.gpuKernel.empty())
            std::printf(" kernel_Mrays_per_s %.2f", median(s.gpuKernel));
        else
            std::printf(" kernel_Mrays_per_s none");
        std::printf("\n");
    }
    std::printf("cpu threads %d primary Mrays_per_s %.2f shadow Mrays_per_s %.2f diffuse Mrays_per_s %.2f\n", a.threads,
                median(series[0].cpu), median(series[1].cpu), median(series[2].cpu));
    const bool haveEmbree = !series[0].embree.empty();
    if (haveEmbree)
        std::printf("embree_high threads %d primary Mrays_per_s %.2f shadow Mrays_per_s %.2f diffuse Mrays_per_s %.2f\n",
                    a.threads, median(series[0].embree), median(series[1].embree), median(series[2].embree));
    std::printf("gpu_cpu_mismatches primary %zu of %zu shadow %zu of %zu diffuse %zu of %zu\n", wrong[0], sets[0].gpu.size(),
                wrong[1], sets[1].gpu.size(), wrong[2], sets[2].gpu.size());
    std::printf("ratio_gpu_over_cpu rounds %d primary %.2f shadow %.2f diffuse %.2f\n", a.rounds,
                median(series[0].gpuOverCpu), median(series[1].gpuOverCpu), median(series[2].gpuOverCpu));
    if (haveEmbree) {
        if (peerShadowRays != sets[1].gpu.size())
            std::printf("note: shadow ray counts differ (vkrt %zu, embree %zu): primary hits disagree on %.3f%% of rays\n",
                        sets[1].gpu.size(), peerShadowRays,
                        100.0 * std::abs(double(sets[1].gpu.size()) - double(peerShadowRays)) / double(sets[0].gpu.size()));
        std::printf("ratio_gpu_over_embree rounds %zu primary %.2f shadow %.2f diffuse %.2f\n", series[0].gpuOverEmbree.size(),
                    median(series[0].gpuOverEmbree), median(series[1].gpuOverEmbree), median(series[2].gpuOverEmbree));
        const double p = median(series[0].gpuOverEmbree), s = median(series[1].gpuOverEmbree);
        std::printf("target gpu_primary_over_embree >= %.2f: %.2f %s\n", kPrimaryTarget, p, p >= kPrimaryTarget ? "met" : "not met");
        std::printf("target gpu_shadow_over_embree >= %.2f: %.2f %s\n", kShadowTarget, s, s >= kShadowTarget ? "met" : "not met");
    }
    std::printf("timed: gpu = GpuTraceStats::traceSeconds (the submissions alone, wall clock from submit to fence: no ray "
                "upload, hit readback or pipeline creation; after a warm-up trace of each kind); kernel = the same submissions "
                "by the device's timestamps (GpuTraceStats::kernelSeconds); cpu = the traversal of the same ray arrays on %d threads; "
                "embree = the peer's own timing, which includes making each ray; Mrays/s and ratios are medians over %d rounds\n",
                a.threads, a.rounds);

    for (Kind k : kKinds) {
        const std::size_t rays = sets[static_cast<int>(k)].gpu.size();
        if (static_cast<double>(wrong[static_cast<int>(k)]) > a.maxMismatchFraction * static_cast<double>(rays)) {
            std::fprintf(stderr, "vkrt-bench gpu rays: GPU and CPU disagree on %zu of %zu %s rays (more than %g of them)\n",
                         wrong[static_cast<int>(k)], rays, name(k), a.maxMismatchFraction);
            return 3;
        }
    }
    return 0;
}

}  // namespace vkrt::bench
