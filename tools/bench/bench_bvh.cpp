// `vkrt-bench bvh MESH.obj|sphere:N [W H SPP THREADS]`: builds vkrt's BVH over the mesh and traces
// primary, shadow and diffuse rays on the CPU exactly as the Embree peer does (camera rule and
// random streams of ../shared/peer/README.md), printing the peer's four lines plus the BVH's size
// and SAH cost. With the peer available (--peer PATH, $VKRT_EMBREE_PEER, or --build-peer), every
// round runs vkrt, then Embree `medium` (for the build), then Embree's default `high` (for
// traversal), alternating, and the median of the per-round ratios vkrt/Embree is printed:
// this machine's speed drifts too much for figures taken minutes apart to be compared.
// Two build figures are printed: the full build (with the CPU traversal's 8-wide copy, which this
// bench traverses) and the build the GPU path needs (BuildOptions::cpuTraversal = false): the
// same build less BuildStats::cpuCopySeconds, its last phase. A separate cpuTraversal = false
// build is not timed instead: run after the full build, it met a warm allocator and read 10-15%
// faster than the copy alone explains; run before it, it made the full build faster.
// A third figure is the tree `vkrt` actually builds for a GPU render (gpu_build_options.h: other
// SAH constants, no 8-wide copy), built after the rays are traced, so with the same warm allocator.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <vector>

#include "bench_args.h"
#include "bench_command.h"
#include "bench_mesh.h"
#include "bench_timing.h"
#include "gpu_build_options.h"
#include "node_layout.h"
#include "peer_rays.h"
#include "peer_runner.h"

namespace vkrt::bench {

namespace {

struct Args {
    std::string source;
    int width = 512, height = 512, spp = 4, threads = 2;
    std::string peer;
    bool buildPeer = false;
    int rounds = 3;
    bvh::BuildOptions build;  // --ctrav, --cisect, --max-leaf, --bins: for measuring the SAH constants
};

Args parseArgs(const std::vector<std::string>& args) {
    Args a;
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--peer" && i + 1 < args.size()) a.peer = args[++i];
        else if (args[i] == "--build-peer") a.buildPeer = true;
        else if (args[i] == "--rounds" && i + 1 < args.size()) a.rounds = positiveInt(args[++i], "--rounds");
        else if (args[i] == "--ctrav" && i + 1 < args.size()) a.build.traversalCost = nonNegativeNumber(args[++i], "--ctrav");
        else if (args[i] == "--cisect" && i + 1 < args.size()) a.build.intersectionCost = nonNegativeNumber(args[++i], "--cisect");
        else if (args[i] == "--max-leaf" && i + 1 < args.size()) a.build.maxLeafSize = positiveInt(args[++i], "--max-leaf");
        else if (args[i] == "--bins" && i + 1 < args.size()) a.build.bins = positiveInt(args[++i], "--bins");
        else if (args[i].rfind("--", 0) == 0) throw std::runtime_error("unknown option " + args[i]);
        else positional.push_back(args[i]);
    }
    if (positional.empty() || positional.size() > 5)
        throw std::runtime_error("usage: vkrt-bench bvh MESH.obj|sphere:N [W H SPP THREADS] [--peer PATH] [--build-peer] [--rounds R] "
                                 "[--ctrav C] [--cisect C] [--max-leaf N] [--bins B]");
    a.source = positional[0];
    if (positional.size() > 1) a.width = positiveInt(positional[1], "W");
    if (positional.size() > 2) a.height = positiveInt(positional[2], "H");
    if (positional.size() > 3) a.spp = positiveInt(positional[3], "SPP");
    if (positional.size() > 4) a.threads = positiveInt(positional[4], "THREADS");
    return a;
}

// SAH cost of group 0's tree under one fixed model (C_trav = C_isect = 1), whatever constants
// built it, so trees built with different constants can be compared:
// sum over inner nodes of A(node)/A(root) + sum over leaves of N * A(leaf)/A(root).
double unitSahCost(const bvh::SceneBvh& scene) {
    if (scene.groups.empty()) return 0.0;
    auto area = [](const bvh::Aabb& b) { return static_cast<double>(b.halfArea()); };
    const bvh::BinaryNode& rootNode = scene.nodes[scene.groups[0].rootNode];
    bvh::Aabb rootBox = bvh::childBox(rootNode, 0);
    if (!bvh::childBox(rootNode, 1).empty()) rootBox.grow(bvh::childBox(rootNode, 1));
    const double rootArea = area(rootBox);
    if (rootArea <= 0.0) return 0.0;
    double cost = 0.0;
    std::vector<std::pair<std::uint32_t, double>> stack{{scene.groups[0].rootNode, rootArea}};
    while (!stack.empty()) {
        const auto [index, nodeArea] = stack.back();
        stack.pop_back();
        cost += nodeArea / rootArea;
        const bvh::BinaryNode& node = scene.nodes[index];
        for (int k = 0; k < 2; ++k) {
            const double a = bvh::childBox(node, k).empty() ? 0.0 : area(bvh::childBox(node, k));
            if (bvh::childCount(node, k) > 0) cost += bvh::childCount(node, k) * a / rootArea;
            else if (bvh::childIsInner(node, k)) stack.push_back({bvh::childLink(node, k), a});
        }
    }
    return cost;
}

struct VkrtFigures {
    bvh::BuildStats stats;
    double gpuOnlyBuildSeconds = 0.0;  // the same build without the 8-wide copy
    double gpuTreeBuildSeconds = 0.0;  // the GPU render's own tree (gpuBuildOptions)
    std::size_t gpuTreeNodes = 0;
    double unitSah = 0.0;
    std::size_t cpuBytes = 0;  // the CPU traversal's 8-wide copy (not uploaded)
    std::size_t triangles = 0, primaryRays = 0, shadowRays = 0;
    double primaryMrays = 0.0, shadowMrays = 0.0, diffuseMrays = 0.0;
};

VkrtFigures measureVkrt(const std::vector<bvh::PrimitiveInput>& prims, const PeerCamera& cam, const Args& a) {
    bvh::BuildOptions options = a.build;
    options.threads = a.threads;
    const std::vector<std::vector<bvh::PrimitiveInput>> groups{prims};
    const std::vector<bvh::InstanceInput> instances{{0, glm::mat4(1.0f), gpu::MATERIAL_NONE}};
    const bvh::SceneBvh scene = bvh::buildSceneBvh(groups, instances, options);

    VkrtFigures f;
    f.stats = scene.stats;
    f.gpuOnlyBuildSeconds = scene.stats.buildSeconds - scene.stats.cpuCopySeconds;
    f.unitSah = unitSahCost(scene);
    f.cpuBytes = scene.cpu.nodes.size() * sizeof(bvh::WideNode);
    f.triangles = prims.size();
    const int w = a.width, spp = a.spp;
    const std::size_t n = static_cast<std::size_t>(w) * a.height * spp;
    std::vector<glm::vec3> hitP(n), hitN(n);
    std::vector<char> hit(n, 0);

    // Each ray is made inside the timed loop, as the peer makes its rays.
    const double tPrimary = overItems(a.height, a.threads, [&](int y) {
        forEachPrimaryRay(cam, w, a.height, spp, y, [&](std::size_t k, const bvh::Ray& ray) {
            bvh::Hit h;
            hit[k] = bvh::intersectClosest(scene, ray, h);
            if (hit[k]) {
                hitP[k] = ray.origin + ray.dir * h.t;
                hitN[k] = facingNormal(scene.prims[h.prim], ray.dir);
            }
        });
    });
    std::size_t hits = 0;
    for (char h : hit) hits += h;
    const double tShadow = overItems(a.height, a.threads, [&](int y) {
        for (std::size_t k = static_cast<std::size_t>(y) * w * spp; k < static_cast<std::size_t>(y + 1) * w * spp; ++k) {
            if (!hit[k]) continue;
            volatile bool blocked = bvh::intersectAny(scene, shadowRay(cam, hitP[k], hitN[k]));
            (void)blocked;
        }
    });
    const double tDiffuse = overItems(a.height, a.threads, [&](int y) {
        DiffuseRow row(y);
        for (std::size_t k = static_cast<std::size_t>(y) * w * spp; k < static_cast<std::size_t>(y + 1) * w * spp; ++k) {
            if (!hit[k]) continue;
            bvh::Hit h;
            volatile bool any = bvh::intersectClosest(scene, row.next(cam, hitP[k], hitN[k]), h);
            (void)any;
        }
    });
    bvh::BuildOptions gpuOptions = gpuBuildOptions();
    gpuOptions.threads = a.threads;
    const bvh::SceneBvh gpuTree = bvh::buildSceneBvh(groups, instances, gpuOptions);
    f.gpuTreeBuildSeconds = gpuTree.stats.buildSeconds;
    f.gpuTreeNodes = gpuTree.stats.nodeCount;
    f.primaryRays = n;
    f.shadowRays = hits;
    f.primaryMrays = n / tPrimary / 1e6;
    f.shadowMrays = hits / tShadow / 1e6;
    f.diffuseMrays = hits / tDiffuse / 1e6;
    return f;
}

}  // namespace

int runBvhBench(const std::vector<std::string>& argv) {
    const Args a = parseArgs(argv);
    const BenchMesh mesh = loadBenchMesh(a.source);
    const std::vector<bvh::PrimitiveInput> prims = toPrimitives(mesh);
    const PeerCamera cam(mesh);
    const std::string peer = locatePeer(a.peer, a.buildPeer);
    if (peer.empty())
        std::fprintf(stderr, "no Embree peer (--peer PATH, $VKRT_EMBREE_PEER or --build-peer): vkrt figures only\n");

    // Alternate vkrt and the peer round by round; keep the best of each side and the ratios of
    // figures taken together.
    std::optional<VkrtFigures> best;
    std::optional<PeerFigures> bestMedium, bestHigh;
    std::vector<double> rBuild, rBuildGpu, rBuildGpuTree, rPrimary, rShadow, rDiffuse;
    for (int round = 0; round < a.rounds; ++round) {
        const VkrtFigures v = measureVkrt(prims, cam, a);
        if (!best) best = v;
        best->stats.buildSeconds = std::min(best->stats.buildSeconds, v.stats.buildSeconds);
        best->gpuOnlyBuildSeconds = std::min(best->gpuOnlyBuildSeconds, v.gpuOnlyBuildSeconds);
        best->gpuTreeBuildSeconds = std::min(best->gpuTreeBuildSeconds, v.gpuTreeBuildSeconds);
        best->primaryMrays = std::max(best->primaryMrays, v.primaryMrays);
        best->shadowMrays = std::max(best->shadowMrays, v.shadowMrays);
        best->diffuseMrays = std::max(best->diffuseMrays, v.diffuseMrays);
        if (peer.empty()) continue;
        const auto medium = runPeer(peer, a.source, a.width, a.height, a.spp, a.threads, "medium");
        const auto high = runPeer(peer, a.source, a.width, a.height, a.spp, a.threads, "high");
        if (!medium || !high) continue;
        if (!bestMedium || medium->buildSeconds < bestMedium->buildSeconds) bestMedium = medium;
        if (!bestHigh) bestHigh = high;
        bestHigh->primaryMrays = std::max(bestHigh->primaryMrays, high->primaryMrays);
        bestHigh->shadowMrays = std::max(bestHigh->shadowMrays, high->shadowMrays);
        bestHigh->diffuseMrays = std::max(bestHigh->diffuseMrays, high->diffuseMrays);
        rBuild.push_back(medium->buildSeconds / v.stats.buildSeconds);
        rBuildGpu.push_back(medium->buildSeconds / v.gpuOnlyBuildSeconds);
        rBuildGpuTree.push_back(medium->buildSeconds / v.gpuTreeBuildSeconds);
        rPrimary.push_back(v.primaryMrays / high->primaryMrays);
        rShadow.push_back(v.shadowMrays / high->shadowMrays);
        rDiffuse.push_back(v.diffuseMrays / high->diffuseMrays);
    }

    const VkrtFigures& v = *best;
    const double tris = static_cast<double>(v.triangles);
    std::printf("triangles %zu build_s %.4f build_Mtris_per_s %.2f\n", v.triangles, v.stats.buildSeconds,
                tris / v.stats.buildSeconds / 1e6);
    std::printf("triangles %zu build_gpu_only_s %.4f build_gpu_only_Mtris_per_s %.2f (the same builds less the CPU's 8-wide copy)\n",
                v.triangles, v.gpuOnlyBuildSeconds, tris / v.gpuOnlyBuildSeconds / 1e6);
    std::printf("triangles %zu build_gpu_tree_s %.4f build_gpu_tree_Mtris_per_s %.2f nodes %zu (the tree a GPU render builds: "
                "C_trav %.1f, no 8-wide copy)\n",
                v.triangles, v.gpuTreeBuildSeconds, tris / v.gpuTreeBuildSeconds / 1e6, v.gpuTreeNodes, kGpuTraversalCost);
    std::printf("primary rays %zu Mrays_per_s %.2f\n", v.primaryRays, v.primaryMrays);
    std::printf("shadow rays %zu Mrays_per_s %.2f\n", v.shadowRays, v.shadowMrays);
    std::printf("diffuse rays %zu Mrays_per_s %.2f\n", v.shadowRays, v.diffuseMrays);
    const double nodeBytes = static_cast<double>(v.stats.nodeCount) * sizeof(bvh::BinaryNode);
    const double primBytes = tris * sizeof(gpu::Primitive);
    std::printf("bvh sah_cost %.2f unit_sah_cost %.2f nodes %zu leaves %zu depth %d node_bytes %.0f prim_bytes %.0f "
                "node_bytes_per_triangle %.1f bytes_per_triangle %.1f cpu_wide_bytes_per_triangle %.1f\n",
                v.stats.sahCost, v.unitSah, v.stats.nodeCount, v.stats.leafCount, v.stats.bottomDepth, nodeBytes,
                primBytes, nodeBytes / tris, (nodeBytes + primBytes) / tris, static_cast<double>(v.cpuBytes) / tris);
    if (bestMedium && bestHigh) {
        std::printf("embree_medium triangles %zu build_s %.4f build_Mtris_per_s %.2f\n", bestMedium->triangles,
                    bestMedium->buildSeconds, bestMedium->buildMtrisPerS);
        std::printf("embree_high build_s %.4f primary Mrays_per_s %.2f shadow Mrays_per_s %.2f diffuse Mrays_per_s %.2f\n",
                    bestHigh->buildSeconds, bestHigh->primaryMrays, bestHigh->shadowMrays, bestHigh->diffuseMrays);
        if (bestHigh->shadowRays != v.shadowRays)
            std::printf("note: shadow ray counts differ (vkrt %zu, embree %zu): primary hits disagree on %.3f%% of rays\n",
                        v.shadowRays, bestHigh->shadowRays,
                        100.0 * std::abs(double(v.shadowRays) - double(bestHigh->shadowRays)) / double(v.primaryRays));
        // build_vs_medium: the full build (GPU arrays + the CPU's 8-wide copy);
        // build_gpu_only_vs_medium: the same build less the copy (cpuTraversal = false);
        // build_gpu_tree_vs_medium: the tree a GPU render builds (gpuBuildOptions).
        std::printf("ratio_vkrt_over_embree rounds %zu build_vs_medium %.2f build_gpu_only_vs_medium %.2f "
                    "build_gpu_tree_vs_medium %.2f primary %.2f shadow %.2f diffuse %.2f\n",
                    rBuild.size(), median(rBuild), median(rBuildGpu), median(rBuildGpuTree), median(rPrimary),
                    median(rShadow), median(rDiffuse));
    }
    return 0;
}

}  // namespace vkrt::bench
