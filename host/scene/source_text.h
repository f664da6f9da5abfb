// A scene file's bytes and the way from a byte offset to "line:column", shared by the XML and the
// JSON source (neither pugixml nor nlohmann::json reports lines of values).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vkrt {

// The whole file. Throws SceneError (`element` names the format: "xml", "json", "scene") when
// the file is missing, not a regular file, larger than the scene-bytes input limit
// (input_limits.h: a file is parsed into a tree several times its size, so a 1 GiB sparse file
// would take gigabytes and a minute before its first error; the size is checked before a byte is
// read) or unreadable.
std::string readSourceFile(const std::string& path, const char* element);

// 1-based line and byte column of offsets into one text.
class LineIndex {
public:
    explicit LineIndex(const std::string& text);
    int lineOf(std::ptrdiff_t offset) const;
    int columnOf(std::ptrdiff_t offset) const;  // bytes since the line's start, plus 1

private:
    std::vector<std::ptrdiff_t> newlineOffsets_;
};

}  // namespace vkrt
