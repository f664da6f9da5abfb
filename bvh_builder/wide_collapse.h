// Two-child trees (SceneBvh::nodes) -> the CPU's 4-wide layout (wide_bvh.h).
#pragma once

#include "bvh.h"

namespace vkrt::bvh {

// Collapses every group's tree and the top level of `bvh` (its nodes, groups and topRoot).
WideBvh collapseToWide(const SceneBvh& bvh);

}  // namespace vkrt::bvh
