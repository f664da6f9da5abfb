#include "primitives.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "node_layout.h"

namespace vkrt::bvh {

namespace {

glm::uvec4 bits(const glm::vec3& v, std::uint32_t w) { return {floatBits(v.x), floatBits(v.y), floatBits(v.z), w}; }
glm::vec3 floats(const glm::uvec4& u) { return {bitsFloat(u.x), bitsFloat(u.y), bitsFloat(u.z)}; }

[[noreturn]] void fail(std::size_t group, std::size_t index, const std::string& what) {
    std::ostringstream msg;
    msg << "bvh: group " << group << ", primitive " << index << ": " << what;
    throw std::invalid_argument(msg.str());
}

std::string str(const glm::vec3& v) {
    std::ostringstream s;
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Aabb boundsOf(const PrimitiveInput& p) {
    Aabb b;
    switch (p.kind) {
    case gpu::PRIM_KIND_TRIANGLE:
        b.grow(p.a);
        b.grow(p.b);
        b.grow(p.c);
        break;
    case gpu::PRIM_KIND_SPHERE:
        b.lo = p.a - glm::vec3(p.b.x);
        b.hi = p.a + glm::vec3(p.b.x);
        break;
    default:  // box
        b.lo = p.a;
        b.hi = p.b;
        break;
    }
    return b;
}

void validate(const PrimitiveInput& p, std::size_t group, std::size_t index) {
    switch (p.kind) {
    case gpu::PRIM_KIND_TRIANGLE:
        if (!finite(p.a) || !finite(p.b) || !finite(p.c))
            fail(group, index, "triangle with a non-finite vertex " + str(p.a) + " " + str(p.b) + " " + str(p.c));
        return;
    case gpu::PRIM_KIND_SPHERE:
        if (!finite(p.a)) fail(group, index, "sphere with a non-finite centre " + str(p.a));
        if (!std::isfinite(p.b.x) || p.b.x < 0.0f)
            fail(group, index, "sphere radius must be finite and >= 0, got " + std::to_string(p.b.x));
        if (!finite(boundsOf(p).lo) || !finite(boundsOf(p).hi))
            fail(group, index, "sphere bounds overflow: centre " + str(p.a) + " radius " + std::to_string(p.b.x));
        return;
    case gpu::PRIM_KIND_BOX:
        if (!finite(p.a) || !finite(p.b)) fail(group, index, "box with a non-finite corner " + str(p.a) + " " + str(p.b));
        if (p.a.x > p.b.x || p.a.y > p.b.y || p.a.z > p.b.z)
            fail(group, index, "box min " + str(p.a) + " exceeds max " + str(p.b));
        return;
    default:
        fail(group, index, "unknown primitive kind " + std::to_string(p.kind));
    }
}

gpu::Primitive encode(const PrimitiveInput& p) {
    gpu::Primitive r{};
    switch (p.kind) {
    case gpu::PRIM_KIND_TRIANGLE:
        r.a = bits(p.a, gpu::PRIM_KIND_TRIANGLE);
        r.b = bits(p.b, 0);
        r.c = bits(p.c, 0);
        break;
    case gpu::PRIM_KIND_SPHERE:
        r.a = bits(p.a, gpu::PRIM_KIND_SPHERE);
        r.b = bits(glm::vec3(p.b.x, 0.0f, 0.0f), 0);
        r.c = glm::uvec4(0);
        break;
    default:
        r.a = bits(p.a, gpu::PRIM_KIND_BOX);
        r.b = bits(p.b, 0);
        r.c = glm::uvec4(0);
        break;
    }
    return r;
}

PrimitiveInput decode(const gpu::Primitive& p) {
    PrimitiveInput r;
    r.kind = gpu::primitiveKind(p.a);
    r.a = floats(p.a);
    r.b = floats(p.b);
    r.c = floats(p.c);
    return r;
}

}  // namespace vkrt::bvh
