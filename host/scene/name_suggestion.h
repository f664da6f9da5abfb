// "did you mean 'sphere'?" after a name a scene format does not know: the one name it does know
// that is close enough to be a typo of it (a swapped, missing, extra or wrong letter, or another
// letter case), and nothing when no name is that close or two are equally close.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace vkrt {

// The edits (insert, delete, substitute, swap two neighbours) that turn `a` into `b`, letter case
// ignored: the optimal-string-alignment form of the Damerau-Levenshtein distance.
int editDistance(std::string_view a, std::string_view b);

// "did you mean 'X'?" for the closest of `known` to `name`, or "" (the rule above).
std::string didYouMean(std::string_view name, const std::vector<std::string_view>& known);

}  // namespace vkrt
