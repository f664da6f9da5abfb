// intersectClosest / intersectAny against brute force (every primitive of every instance).
// Both pick the closest hit by the rule of shaders/shared/hit_order.h (distances in 256-ulp
// buckets, then the lower instance and primitive), so the same primitive is expected.
// Tolerance: t within 1e-6 relative. Both sides run the same float primitive tests on the same
// primitive and object-space ray (see brute_force.h), so t should agree to the last bit; the
// tolerance only leaves room for a future change of evaluation order. A different primitive is accepted only as a tie: the BVH's primitive must be hit by the
// brute-force test at the same t (coincident surfaces, shared edges), and ties must be rare.
#include <filesystem>

#include <gtest/gtest.h>
#include <pugixml.hpp>

#include "brute_force.h"
#include "test_paths.h"

namespace vkrt::bvh::test {
namespace {

constexpr float kRelTol = 1e-6f;

bool close(float a, float b) { return std::abs(a - b) <= kRelTol * std::max(std::abs(a), std::abs(b)); }

std::string describe(const Ray& r) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "ray o=(%.9g %.9g %.9g) d=(%.9g %.9g %.9g) tmax=%.9g", r.origin.x, r.origin.y,
                  r.origin.z, r.dir.x, r.dir.y, r.dir.z, r.tmax);
    return buf;
}

// Checks every ray; returns the number of hits (so callers can assert the rays were not all misses).
std::size_t expectMatchesBruteForce(const TestScene& scene, const std::vector<Ray>& rays,
                                    const BuildOptions& options = {}) {
    const SceneBvh bvh = buildSceneBvh(scene.groups, scene.instances, options);
    const FlatIndex flat = flatIndexOf(bvh);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 2.0f);
    std::size_t hits = 0, ties = 0, anyChecked = 0;
    for (const Ray& ray : rays) {
        BruteHit ref;
        const bool refHit = bruteClosest(scene, bvh.instances, flat, ray, ref);
        Hit hit;
        const bool got = intersectClosest(bvh, ray, hit);
        EXPECT_EQ(got, refHit) << describe(ray) << (refHit ? " brute t=" + std::to_string(ref.t) : "");
        if (got && refHit) {
            ++hits;
            if (hit.instance >= scene.instances.size()) {
                ADD_FAILURE() << "hit instance " << hit.instance << " out of range";
                continue;
            }
            const GroupRange& g = bvh.groups[scene.instances[hit.instance].group];
            if (hit.prim < g.firstPrim || hit.prim >= g.firstPrim + g.primCount) {
                ADD_FAILURE() << "hit primitive " << hit.prim << " outside the instance's group";
                continue;
            }
            const std::uint32_t source = bvh.primSource[hit.prim];
            EXPECT_TRUE(close(hit.t, ref.t)) << describe(ray) << " bvh t=" << hit.t << " brute t=" << ref.t;
            if (hit.instance != ref.instance || source != ref.sourcePrim) {
                float tAlt = 0.0f;
                EXPECT_TRUE(bruteOne(scene, bvh.instances, hit.instance, source, ray, tAlt) && close(tAlt, ref.t))
                    << describe(ray) << " bvh hit (instance " << hit.instance << ", prim " << source
                    << ") is not a closest hit; brute force: (instance " << ref.instance << ", prim "
                    << ref.sourcePrim << ") t=" << ref.t;
                ++ties;
            }
        }
        // Shadow query with a random tmax (sometimes shorter, sometimes longer than the closest hit).
        Ray shadow = ray;
        shadow.tmax = refHit ? ref.t * u(rng) : u(rng) * 1e3f;
        if (refHit && close(shadow.tmax, ref.t)) continue;  // too close to call either way
        ++anyChecked;
        EXPECT_EQ(intersectAny(bvh, shadow), bruteAny(scene, bvh.instances, shadow)) << "any-hit " << describe(shadow);
    }
    EXPECT_LE(ties, rays.size() / 100 + 1) << "too many ties to be coincidences";
    EXPECT_GT(anyChecked, rays.size() / 2);
    return hits;
}

TEST(TraversalVsBruteForce, RandomTriangleSoups) {
    std::mt19937 rng(1);
    for (const auto& [count, size] : std::vector<std::pair<int, float>>{{1, 1.0f}, {7, 3.0f}, {100, 2.0f}, {5000, 0.5f}, {3000, 20.0f}}) {
        SCOPED_TRACE("triangles " + std::to_string(count) + " size " + std::to_string(size));
        const TestScene scene = singleGroup(randomTriangles(rng, count, 20.0f, size));
        const std::size_t hits = expectMatchesBruteForce(scene, randomRays(rng, scene, 1500));
        EXPECT_GT(hits, 150u);
    }
}

TEST(TraversalVsBruteForce, UpstreamMeshes) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    const std::filesystem::path dir = vkrt::test::upstreamDir() + "/objFiles";
    ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
    std::vector<std::filesystem::path> meshes;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".obj") meshes.push_back(e.path());
    std::sort(meshes.begin(), meshes.end());
    ASSERT_GE(meshes.size(), 6u);
    std::mt19937 rng(2);
    for (const auto& path : meshes) {
        SCOPED_TRACE(path.string());
        const TestScene scene = singleGroup(loadObjTriangles(path.string()));
        ASSERT_FALSE(scene.groups[0].empty());
        // Brute force costs rays x triangles: fewer rays for the 100K-triangle meshes.
        const std::size_t rays = scene.groups[0].size() > 20000 ? 250 : 1000;
        const std::size_t hits = expectMatchesBruteForce(scene, randomRays(rng, scene, rays));
        EXPECT_GT(hits, rays / 5);
    }
}

TEST(TraversalVsBruteForce, RandomSpheresAndBoxes) {
    std::mt19937 rng(3);
    const TestScene scene = singleGroup(randomSpheresAndBoxes(rng, 2000, 100.0f, 3.0f));
    EXPECT_GT(expectMatchesBruteForce(scene, randomRays(rng, scene, 3000)), 1000u);
}

// The loose spheres and boxes of upstream scenes (spheres_1K.xml: 1000 spheres;
// boxSphereTest.xml: walls as boxes, trees of spheres).
std::vector<PrimitiveInput> xmlSpheresAndBoxes(const std::string& path) {
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_file(path.c_str())) << path;
    auto vec = [](const pugi::xml_node& n) {
        glm::vec3 v;
        std::sscanf(n.child_value(), "%f %f %f", &v.x, &v.y, &v.z);
        return v;
    };
    std::vector<PrimitiveInput> out;
    for (const auto& shape : doc.child("scene").children("shape")) {
        const std::string type = shape.attribute("type").value();
        PrimitiveInput p;
        if (type == "sphere") {
            p.kind = gpu::PRIM_KIND_SPHERE;
            p.a = vec(shape.child("center"));
            p.b.x = std::stof(shape.child_value("radius"));
        } else if (type == "box") {
            p.kind = gpu::PRIM_KIND_BOX;
            p.a = vec(shape.child("minPt"));
            p.b = vec(shape.child("maxPt"));
        } else {
            continue;
        }
        out.push_back(p);
    }
    return out;
}

TEST(TraversalVsBruteForce, UpstreamSphereAndBoxScenes) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    std::mt19937 rng(4);
    for (const char* name : {"spheres_1K.xml", "boxSphereTest.xml"}) {
        SCOPED_TRACE(name);
        const TestScene scene = singleGroup(xmlSpheresAndBoxes(vkrt::test::upstreamDir() + "/" + name));
        ASSERT_GE(scene.groups[0].size(), 10u);
        EXPECT_GT(expectMatchesBruteForce(scene, randomRays(rng, scene, 2000)), 400u);
    }
}

// Groups placed by rotated, non-uniformly scaled and mirrored instances, plus the loose group.
TEST(TraversalVsBruteForce, InstancedScenes) {
    VKRT_SKIP_WITHOUT(vkrt::test::upstreamDir());
    std::mt19937 rng(5);
    TestScene scene;
    scene.groups.push_back(randomSpheresAndBoxes(rng, 50, 30.0f, 2.0f));          // loose shapes
    scene.groups.push_back(randomTriangles(rng, 400, 5.0f, 1.0f));                // a prototype
    scene.groups.push_back(randomSpheresAndBoxes(rng, 60, 5.0f, 0.7f));           // another
    scene.groups.push_back(loadObjTriangles(vkrt::test::upstreamDir() + "/objFiles/icosahedron.obj"));
    scene.groups.push_back({});                                                    // empty group
    scene.instances.push_back({0, glm::mat4(1.0f), gpu::MATERIAL_NONE});
    for (int i = 0; i < 40; ++i) {
        const auto group = static_cast<std::uint32_t>(1 + i % 4);
        scene.instances.push_back({group, randomTransform(rng, 30.0f, i % 3 == 0), static_cast<std::uint32_t>(i)});
    }
    EXPECT_GT(expectMatchesBruteForce(scene, randomRays(rng, scene, 3000)), 800u);
}

TEST(TraversalVsBruteForce, IdenticalCentroids) {
    std::mt19937 rng(6);
    std::vector<PrimitiveInput> prims;
    // 300 copies of one triangle, then 300 concentric spheres: nothing to bin, only median splits.
    const auto tri = randomTriangles(rng, 1, 1.0f, 1.0f)[0];
    for (int i = 0; i < 300; ++i) prims.push_back(tri);
    for (int i = 0; i < 300; ++i) prims.push_back({gpu::PRIM_KIND_SPHERE, glm::vec3(5.0f), glm::vec3(0.01f * (i + 1)), {}});
    const TestScene scene = singleGroup(prims);
    // Copies of one triangle all tie: the tie rule accepts any of them, but they are 300 ties.
    const SceneBvh bvh = buildSceneBvh(scene.groups, scene.instances);
    const FlatIndex flat = flatIndexOf(bvh);
    for (const Ray& ray : randomRays(rng, scene, 500)) {
        BruteHit ref;
        Hit hit;
        const bool refHit = bruteClosest(scene, bvh.instances, flat, ray, ref);
        ASSERT_EQ(intersectClosest(bvh, ray, hit), refHit) << describe(ray);
        if (refHit) {
            EXPECT_TRUE(close(hit.t, ref.t)) << describe(ray);
        }
        EXPECT_EQ(intersectAny(bvh, ray), refHit);
    }
}

TEST(TraversalVsBruteForce, FlatAndLongPrimitives) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<PrimitiveInput> prims;
    for (int i = 0; i < 500; ++i) {  // axis-aligned flat triangles in the plane z = 0 (zero-thickness boxes)
        const glm::vec3 c(100.0f * u(rng), 100.0f * u(rng), 0.0f);
        prims.push_back({gpu::PRIM_KIND_TRIANGLE, c, c + glm::vec3(3.0f * u(rng), 0.0f, 0.0f),
                         c + glm::vec3(0.0f, 3.0f * u(rng), 0.0f)});
    }
    for (int i = 0; i < 300; ++i) {  // needles: 1000 long, 1e-3 wide, along random axes
        const glm::vec3 c(100.0f * u(rng), 100.0f * u(rng), 10.0f * u(rng));
        glm::vec3 along(0.0f), across(0.0f);
        along[i % 3] = 1000.0f;
        across[(i + 1) % 3] = 1e-3f;
        prims.push_back({gpu::PRIM_KIND_TRIANGLE, c - along * 0.5f, c + along * 0.5f, c + across});
    }
    for (int i = 0; i < 100; ++i) {  // flat boxes and thin slabs
        const glm::vec3 c(100.0f * u(rng), 100.0f * u(rng), 20.0f);
        prims.push_back({gpu::PRIM_KIND_BOX, c, c + glm::vec3(5.0f, 5.0f, i % 2 ? 0.0f : 1e-4f), {}});
    }
    const TestScene scene = singleGroup(prims);
    EXPECT_GT(expectMatchesBruteForce(scene, randomRays(rng, scene, 3000)), 500u);
}

TEST(TraversalVsBruteForce, DepthBoundedTree) {
    std::mt19937 rng(8);
    const TestScene scene = singleGroup(randomTriangles(rng, 3000, 10.0f, 0.3f));
    BuildOptions options;
    options.maxBottomDepth = 10;  // 3000 / 8 leaves need 9 levels: the bound forces median splits
    const SceneBvh bvh = buildSceneBvh(scene.groups, scene.instances, options);
    EXPECT_LE(bvh.stats.bottomDepth, 10);
    EXPECT_GT(expectMatchesBruteForce(scene, randomRays(rng, scene, 1000), options), 200u);
}

}  // namespace
}  // namespace vkrt::bvh::test
