// `vkrt-bench bvh MESH.obj|sphere:N [W H SPP THREADS]`: builds vkrt's BVH over the mesh and traces
// primary, shadow and diffuse rays on the CPU exactly as the Embree peer does (camera rule and
// random streams of ../shared/peer/README.md), printing the peer's four lines plus the BVH's size
// and SAH cost. With the peer available (--peer PATH, $VKRT_EMBREE_PEER, or --build-peer), every
// round runs vkrt, then Embree `medium` (for the build), then Embree's default `high` (for
// traversal), alternating, and the median of the per-round ratios vkrt/Embree is printed:
// this machine's speed drifts too much for figures taken minutes apart to be compared.
#include <algorithm>
#include <bit>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <stdexcept>
#include <thread>
#include <vector>

#include "bench_command.h"
#include "bench_mesh.h"
#include "node_layout.h"
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

float number(const std::string& s, const char* what) {
    char* end = nullptr;
    const float v = std::strtof(s.c_str(), &end);
    if (end == s.c_str() || *end || !(v >= 0.0f)) throw std::runtime_error(std::string(what) + " must be a number >= 0, got '" + s + "'");
    return v;
}

int positive(const std::string& s, const char* what) {
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (end == s.c_str() || *end || v < 1 || v > 1 << 20)
        throw std::runtime_error(std::string(what) + " must be a positive integer, got '" + s + "'");
    return static_cast<int>(v);
}

Args parseArgs(const std::vector<std::string>& args) {
    Args a;
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--peer" && i + 1 < args.size()) a.peer = args[++i];
        else if (args[i] == "--build-peer") a.buildPeer = true;
        else if (args[i] == "--rounds" && i + 1 < args.size()) a.rounds = positive(args[++i], "--rounds");
        else if (args[i] == "--ctrav" && i + 1 < args.size()) a.build.traversalCost = number(args[++i], "--ctrav");
        else if (args[i] == "--cisect" && i + 1 < args.size()) a.build.intersectionCost = number(args[++i], "--cisect");
        else if (args[i] == "--max-leaf" && i + 1 < args.size()) a.build.maxLeafSize = positive(args[++i], "--max-leaf");
        else if (args[i] == "--bins" && i + 1 < args.size()) a.build.bins = positive(args[++i], "--bins");
        else if (args[i].rfind("--", 0) == 0) throw std::runtime_error("unknown option " + args[i]);
        else positional.push_back(args[i]);
    }
    if (positional.empty() || positional.size() > 5)
        throw std::runtime_error("usage: vkrt-bench bvh MESH.obj|sphere:N [W H SPP THREADS] [--peer PATH] [--build-peer] [--rounds R] "
                                 "[--ctrav C] [--cisect C] [--max-leaf N] [--bins B]");
    a.source = positional[0];
    if (positional.size() > 1) a.width = positive(positional[1], "W");
    if (positional.size() > 2) a.height = positive(positional[2], "H");
    if (positional.size() > 3) a.spp = positive(positional[3], "SPP");
    if (positional.size() > 4) a.threads = positive(positional[4], "THREADS");
    return a;
}

// The peer's camera rule (../shared/peer/README.md).
struct Camera {
    glm::vec3 centre, eye, fwd, right, up, light;
    float radius;
    explicit Camera(const BenchMesh& m) {
        centre = (m.lo + m.hi) * 0.5f;
        const glm::vec3 ext = m.hi - m.lo;
        radius = 0.5f * std::sqrt(glm::dot(ext, ext));
        eye = centre + normalised(glm::vec3(0.6f, 0.4f, 1.0f)) * (1.5f * radius);
        fwd = normalised(centre - eye);
        right = normalised(glm::cross(fwd, glm::vec3(0.0f, 1.0f, 0.0f)));
        up = glm::cross(right, fwd);
        light = centre + glm::vec3(radius * 2.0f, radius * 3.0f, radius * 2.0f);
    }
    // Scaling by the reciprocal length (not dividing) matches the peer's rounding.
    static glm::vec3 normalised(const glm::vec3& v) { return v * (1.0f / std::sqrt(glm::dot(v, v))); }
};

// Runs body(y) for every image row on `threads` threads, rows handed out one at a time. Seconds.
template <class Body>
double overRows(int rows, int threads, Body&& body) {
    std::atomic<int> next{0};
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (int y; (y = next++) < rows;) body(y);
        });
    for (std::thread& t : pool) t.join();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// SAH cost of group 0's tree under one fixed model (C_trav = C_isect = 1), whatever constants
// built it, so trees built with different constants can be compared:
// sum over inner nodes of A(node)/A(root) + sum over leaves of N * A(leaf)/A(root).
double unitSahCost(const bvh::SceneBvh& scene) {
    if (scene.groups.empty()) return 0.0;
    auto area = [](const bvh::Aabb& b) { return static_cast<double>(b.halfArea()); };
    const gpu::BvhNode& rootNode = scene.nodes[scene.groups[0].rootNode];
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
        const gpu::BvhNode& node = scene.nodes[index];
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
    double unitSah = 0.0;
    std::size_t cpuBytes = 0;  // the CPU traversal's 4-wide copy (not uploaded)
    std::size_t triangles = 0, primaryRays = 0, shadowRays = 0;
    double primaryMrays = 0.0, shadowMrays = 0.0, diffuseMrays = 0.0;
};

VkrtFigures measureVkrt(const std::vector<bvh::PrimitiveInput>& prims, const Camera& cam, const Args& a) {
    bvh::BuildOptions options = a.build;
    options.threads = a.threads;
    const std::vector<std::vector<bvh::PrimitiveInput>> groups{prims};
    const std::vector<bvh::InstanceInput> instances{{0, glm::mat4(1.0f), gpu::MATERIAL_NONE}};
    const bvh::SceneBvh scene = bvh::buildSceneBvh(groups, instances, options);

    VkrtFigures f;
    f.stats = scene.stats;
    f.unitSah = unitSahCost(scene);
    f.cpuBytes = scene.cpu.nodes.size() * sizeof(bvh::WideNode);
    f.triangles = prims.size();
    const int w = a.width, spp = a.spp;
    const std::size_t n = static_cast<std::size_t>(w) * a.height * spp;
    std::vector<glm::vec3> hitP(n), hitN(n);
    std::vector<char> hit(n, 0);
    auto facingNormal = [&](const bvh::Hit& h, const glm::vec3& d) {
        const gpu::Primitive& p = scene.prims[h.prim];
        auto vtx = [](const glm::uvec4& u) {
            return glm::vec3(std::bit_cast<float>(u.x), std::bit_cast<float>(u.y), std::bit_cast<float>(u.z));
        };
        const glm::vec3 v0 = vtx(p.a);
        glm::vec3 ng = Camera::normalised(glm::cross(vtx(p.b) - v0, vtx(p.c) - v0));
        return glm::dot(ng, d) > 0.0f ? -ng : ng;
    };

    const double tPrimary = overRows(a.height, a.threads, [&](int y) {
        std::mt19937 rng(y);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (int x = 0; x < w; ++x)
            for (int s = 0; s < spp; ++s) {
                const std::size_t k = (static_cast<std::size_t>(y) * w + x) * spp + s;
                const float px = (x + u(rng)) / w * 2 - 1;
                const float py = 1 - (y + u(rng)) / a.height * 2;
                const glm::vec3 d = Camera::normalised(cam.fwd + cam.right * (px * 0.8f) + cam.up * (py * 0.8f));
                bvh::Ray ray{cam.eye, d, 1e30f};
                bvh::Hit h;
                hit[k] = bvh::intersectClosest(scene, ray, h);
                if (hit[k]) {
                    hitP[k] = cam.eye + d * h.t;
                    hitN[k] = facingNormal(h, d);
                }
            }
    });
    std::size_t hits = 0;
    for (char h : hit) hits += h;
    const double offset = 1e-4 * cam.radius;
    const double tShadow = overRows(a.height, a.threads, [&](int y) {
        for (std::size_t k = static_cast<std::size_t>(y) * w * spp; k < static_cast<std::size_t>(y + 1) * w * spp; ++k) {
            if (!hit[k]) continue;
            const glm::vec3 o = hitP[k] + hitN[k] * static_cast<float>(offset);
            glm::vec3 d = cam.light - o;
            const float len = std::sqrt(glm::dot(d, d));
            d = d * (1 / len);
            volatile bool blocked = bvh::intersectAny(scene, bvh::Ray{o, d, len});
            (void)blocked;
        }
    });
    const double tDiffuse = overRows(a.height, a.threads, [&](int y) {
        std::mt19937 rng(1000 + y);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        for (std::size_t k = static_cast<std::size_t>(y) * w * spp; k < static_cast<std::size_t>(y + 1) * w * spp; ++k) {
            if (!hit[k]) continue;
            const glm::vec3 nrm = hitN[k];
            const glm::vec3 axis = std::fabs(nrm.x) > 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            const glm::vec3 t = Camera::normalised(glm::cross(axis, nrm)), b = glm::cross(nrm, t);
            const float r1 = u(rng), r2 = u(rng), sr = std::sqrt(r1);
            const float ph = static_cast<float>(2 * M_PI * r2);
            const glm::vec3 d = Camera::normalised(t * (sr * std::cos(ph)) + b * (sr * std::sin(ph)) + nrm * std::sqrt(1 - r1));
            const glm::vec3 o = hitP[k] + nrm * static_cast<float>(offset);
            bvh::Hit h;
            volatile bool any = bvh::intersectClosest(scene, bvh::Ray{o, d, 1e30f}, h);
            (void)any;
        }
    });
    f.primaryRays = n;
    f.shadowRays = hits;
    f.primaryMrays = n / tPrimary / 1e6;
    f.shadowMrays = hits / tShadow / 1e6;
    f.diffuseMrays = hits / tDiffuse / 1e6;
    return f;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

}  // namespace

int runBvhBench(const std::vector<std::string>& argv) {
    const Args a = parseArgs(argv);
    const BenchMesh mesh = loadBenchMesh(a.source);
    const std::vector<bvh::PrimitiveInput> prims = toPrimitives(mesh);
    const Camera cam(mesh);
    const std::string peer = locatePeer(a.peer, a.buildPeer);
    if (peer.empty())
        std::fprintf(stderr, "no Embree peer (--peer PATH, $VKRT_EMBREE_PEER or --build-peer): vkrt figures only\n");

    // Alternate vkrt and the peer round by round; keep the best of each side and the ratios of
    // figures taken together.
    std::optional<VkrtFigures> best;
    std::optional<PeerFigures> bestMedium, bestHigh;
    std::vector<double> rBuild, rPrimary, rShadow, rDiffuse;
    for (int round = 0; round < a.rounds; ++round) {
        const VkrtFigures v = measureVkrt(prims, cam, a);
        if (!best) best = v;
        best->stats.buildSeconds = std::min(best->stats.buildSeconds, v.stats.buildSeconds);
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
        rPrimary.push_back(v.primaryMrays / high->primaryMrays);
        rShadow.push_back(v.shadowMrays / high->shadowMrays);
        rDiffuse.push_back(v.diffuseMrays / high->diffuseMrays);
    }

    const VkrtFigures& v = *best;
    const double tris = static_cast<double>(v.triangles);
    std::printf("triangles %zu build_s %.4f build_Mtris_per_s %.2f\n", v.triangles, v.stats.buildSeconds,
                tris / v.stats.buildSeconds / 1e6);
    std::printf("primary rays %zu Mrays_per_s %.2f\n", v.primaryRays, v.primaryMrays);
    std::printf("shadow rays %zu Mrays_per_s %.2f\n", v.shadowRays, v.shadowMrays);
    std::printf("diffuse rays %zu Mrays_per_s %.2f\n", v.shadowRays, v.diffuseMrays);
    const double nodeBytes = static_cast<double>(v.stats.nodeCount) * sizeof(gpu::BvhNode);
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
        std::printf("ratio_vkrt_over_embree rounds %zu build_vs_medium %.2f primary %.2f shadow %.2f diffuse %.2f\n",
                    rBuild.size(), median(rBuild), median(rPrimary), median(rShadow), median(rDiffuse));
    }
    return 0;
}

}  // namespace vkrt::bench
