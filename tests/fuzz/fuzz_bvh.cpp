// libFuzzer target: the BVH builder (bvh_builder/bvh.h) on any primitives and instances, huge and
// degenerate ones included (issue 38: a sphere at 1.8e38 once overflowed a bound to inf and a bin
// index to -2^31). The builder must answer with a tree or with its std::invalid_argument; the tree
// must hold each group's primitives exactly once, and rays through it must not crash or return a
// hit outside (0, tmax).
//
// Input: byte 0 = groups (1-3), byte 1 = instances (1-4); then per instance a group byte and 12
// floats (the affine rows of objectToWorld); then per primitive a byte (group, kind) and 9 floats
// (a, b, c). Floats are raw bits, so NaN, inf, denormals and 3.4e38 all come up.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "bvh.h"

namespace {

class Reader {
public:
    Reader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    bool has(std::size_t n) const { return at_ + n <= size_; }
    std::uint8_t byte() { return data_[at_++]; }
    float number() {
        float f;
        std::memcpy(&f, data_ + at_, sizeof f);
        at_ += sizeof f;
        return f;
    }
    glm::vec3 vec3() {
        const float x = number(), y = number(), z = number();
        return {x, y, z};
    }

private:
    const std::uint8_t* data_;
    std::size_t size_, at_ = 0;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace vkrt;
    Reader in(data, size);
    if (!in.has(2)) return 0;
    const int groupCount = 1 + in.byte() % 3, instanceCount = 1 + in.byte() % 4;
    std::vector<bvh::InstanceInput> instances;
    for (int i = 0; i < instanceCount && in.has(1 + 12 * sizeof(float)); ++i) {
        bvh::InstanceInput instance;
        instance.group = in.byte() % groupCount;
        for (int row = 0; row < 3; ++row)
            for (int column = 0; column < 4; ++column) instance.objectToWorld[column][row] = in.number();
        instances.push_back(instance);
    }
    std::vector<std::vector<bvh::PrimitiveInput>> groups(static_cast<std::size_t>(groupCount));
    while (in.has(1 + 9 * sizeof(float))) {
        const std::uint8_t tag = in.byte();
        bvh::PrimitiveInput p;
        p.kind = (tag >> 2) % 3 == 0 ? gpu::PRIM_KIND_TRIANGLE : (tag >> 2) % 3 == 1 ? gpu::PRIM_KIND_SPHERE : gpu::PRIM_KIND_BOX;
        p.a = in.vec3();
        p.b = in.vec3();
        p.c = in.vec3();
        groups[tag % groupCount].push_back(p);
    }

    bvh::BuildOptions options;
    options.threads = 1;
    bvh::SceneBvh tree;
    try {
        tree = bvh::buildSceneBvh(groups, instances, options);
    } catch (const std::invalid_argument&) {
        return 0;  // the documented answer to bad input
    }

    // Each group's primitives exactly once.
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const bvh::GroupRange& range = tree.groups.at(g);
        if (range.primCount != groups[g].size()) std::abort();
        std::vector<bool> seen(groups[g].size(), false);
        for (std::uint32_t k = range.firstPrim; k < range.firstPrim + range.primCount; ++k) {
            const std::uint32_t source = tree.primSource.at(k);
            if (source >= seen.size() || seen[source]) std::abort();
            seen[source] = true;
        }
    }
    // Rays along the axes from the origin and from a primitive's corner.
    std::vector<glm::vec3> origins = {glm::vec3(0.0f)};
    for (const auto& group : groups)
        if (!group.empty()) origins.push_back(group.front().a);
    for (const glm::vec3& origin : origins)
        for (int axis = 0; axis < 3; ++axis)
            for (float sign : {-1.0f, 1.0f}) {
                bvh::Ray ray;
                ray.origin = origin;
                ray.dir = glm::vec3(0.0f);
                ray.dir[axis] = sign;
                bvh::Hit hit;
                if (bvh::intersectClosest(tree, ray, hit) && !(hit.t > 0.0f && hit.t < ray.tmax)) std::abort();
                (void)bvh::intersectAny(tree, ray);
            }
    return 0;
}
