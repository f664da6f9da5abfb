// A PrimitiveInput's bounds, its check, and its gpu::Primitive record (layout in device_host.h).
#pragma once

#include <cstddef>

#include "aabb.h"
#include "bvh.h"

namespace vkrt::bvh {

Aabb boundsOf(const PrimitiveInput& p);

// Throws std::invalid_argument naming the group, the primitive and the bad value: an unknown kind,
// a non-finite coordinate, a negative radius, or a box whose min exceeds its max.
void validate(const PrimitiveInput& p, std::size_t group, std::size_t index);

gpu::Primitive encode(const PrimitiveInput& p);
// The inverse of encode (the traversal and the tests read primitives back through it).
PrimitiveInput decode(const gpu::Primitive& p);

}  // namespace vkrt::bvh
