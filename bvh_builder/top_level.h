// The top level: instance records (the three 3x4 matrices the kernels read) and a SAH tree over the
// instances' world boxes whose leaves hold exactly one instance each (leaf link = instance index,
// count = 1), so instances keep their input order.
#pragma once

#include <cstddef>
#include <vector>

#include "bvh.h"
#include "flatten.h"

namespace vkrt::bvh {

// Throws std::invalid_argument naming the instance when the transform is not affine, not finite
// or singular.
gpu::Instance makeInstance(const InstanceInput& in, std::uint32_t bottomRoot, std::size_t index);

// Whether the instance leaves rays unchanged (both 3x4 matrices exactly the identity): the kernels
// skip the top level for a lone identity instance and walk an identity world group inline.
bool isIdentity(const gpu::Instance& instance);

// World box of an object box: the box of its 8 transformed corners, computed in double and
// widened by a few ulps so rounding never puts an object-space hit outside it.
Aabb worldBounds(const Aabb& objectBox, const glm::mat4& objectToWorld);

// Appends the top-level tree over worldBoxes (instances with an empty box are left out: nothing
// can hit them) to nodes.
FlattenResult buildTopLevel(const std::vector<Aabb>& worldBoxes, const SahParams& params, ThreadPool& pool,
                            std::vector<BinaryNode>& nodes);

}  // namespace vkrt::bvh
