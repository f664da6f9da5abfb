#include "name_suggestion.h"

#include <algorithm>
#include <cctype>

namespace vkrt {

namespace {
bool sameLetter(char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
}
}  // namespace

int editDistance(std::string_view a, std::string_view b) {
    // d[i][j]: the distance between a's first i and b's first j characters.
    std::vector<std::vector<int>> d(a.size() + 1, std::vector<int>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = static_cast<int>(i);
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = static_cast<int>(j);
    for (std::size_t i = 1; i <= a.size(); ++i) {
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const int cost = sameLetter(a[i - 1], b[j - 1]) ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && sameLetter(a[i - 1], b[j - 2]) && sameLetter(a[i - 2], b[j - 1]))
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    }
    return d[a.size()][b.size()];
}

// At most 2 edits, and at most one per 3 letters of the name: "shpere" is a typo of "sphere", but
// "v3" is not one of "v0" (each of v0, v1, v2 is as close, and v3 is no typo of any of them).
std::string didYouMean(std::string_view name, const std::vector<std::string_view>& known) {
    const int allowed = std::min(2, static_cast<int>(name.size()) / 3);
    int best = allowed + 1;
    std::string_view closest;
    bool tie = false;
    for (std::string_view candidate : known) {
        const int distance = editDistance(name, candidate);
        if (distance < best) {
            best = distance;
            closest = candidate;
            tie = false;
        } else if (distance == best && editDistance(candidate, closest) > 0) {
            tie = true;  // two different names (envMapPrefix and envmapPrefix are one name here)
        }
    }
    if (best > allowed || tie) return "";
    return "did you mean '" + std::string(closest) + "'?";
}

}  // namespace vkrt
