#include "source_text.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "diagnostics.h"
#include "input_limits.h"

namespace vkrt {

std::string readSourceFile(const std::string& path, const char* element) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw SceneError({path, 0, element, "scene file not found", path});
    if (!std::filesystem::is_regular_file(path, ec)) throw SceneError({path, 0, element, "not a regular file", path});
    if (const std::uintmax_t size = std::filesystem::file_size(path, ec); !ec && size > inputLimits().sceneFileBytes)
        throw SceneError({path, 0, element,
                          "the file is " + std::to_string(size) + " bytes; a scene file may have at most " +
                              std::to_string(inputLimits().sceneFileBytes) + " (meshes go in OBJ files)" +
                              inputLimitHint("scene-bytes"),
                          path});
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError({path, 0, element, "cannot open the scene file", path});
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw SceneError({path, 0, element, "cannot read the scene file", path});
    return buffer.str();
}

LineIndex::LineIndex(const std::string& text) {
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') newlineOffsets_.push_back(static_cast<std::ptrdiff_t>(i));
}

int LineIndex::lineOf(std::ptrdiff_t offset) const {
    const auto before = std::lower_bound(newlineOffsets_.begin(), newlineOffsets_.end(), offset);
    return static_cast<int>(std::distance(newlineOffsets_.begin(), before)) + 1;
}

int LineIndex::columnOf(std::ptrdiff_t offset) const {
    const int line = lineOf(offset);
    const std::ptrdiff_t lineStart = line == 1 ? 0 : newlineOffsets_[static_cast<std::size_t>(line - 2)] + 1;
    return static_cast<int>(offset - lineStart) + 1;
}

}  // namespace vkrt
