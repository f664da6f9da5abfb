#include "obj_validation.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "number_text.h"

namespace vkrt {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

std::vector<std::string_view> tokens(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isBlank(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !isBlank(line[i])) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

[[noreturn]] void fail(std::size_t line, std::string_view keyword, const std::string& problem, std::string_view value) {
    throw std::runtime_error("OBJ line " + std::to_string(line) + ": " + std::string(keyword) + ": " + problem +
                             (value.empty() ? std::string() : " '" + std::string(value) + "'"));
}

// A coordinate as the loaders read numbers: the whole token, finite, within float.
void checkCoordinate(std::size_t line, std::string_view keyword, std::string_view token) {
    double value = 0.0;
    const std::size_t skip = token.size() > 1 && token[0] == '+' ? 1 : 0;  // tinyobjloader takes "+1"; from_chars does not
    const auto [end, error] = std::from_chars(token.data() + skip, token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size() || !finiteFloat(value))
        fail(line, keyword, "not a finite 32-bit number", token);
}

struct Kind {
    const char* name;         // for messages
    std::size_t defined = 0;  // lines of this kind so far
};

// One index of a face corner ("12", "-3"), as written.
void checkIndex(std::size_t line, std::string_view part, Kind& kind) {
    long long index = 0;
    const char* begin = part.data() + (part.front() == '+' ? 1 : 0);
    const auto [end, error] = std::from_chars(begin, part.data() + part.size(), index);
    if (error == std::errc::result_out_of_range || (error == std::errc() && (index > INT32_MAX || index < -INT32_MAX)))
        fail(line, "f", std::string(kind.name) + " index beyond the range of an int", part);
    if (error != std::errc() || end != part.data() + part.size()) fail(line, "f", std::string(kind.name) + " index is not an integer", part);
    if (index == 0) fail(line, "f", std::string(kind.name) + " index 0 (OBJ indices start at 1, or count back from -1)", part);
    if (index < 0 && static_cast<std::size_t>(-index) > kind.defined)
        fail(line, "f", std::string(kind.name) + " index counts back past the first one (" + std::to_string(kind.defined) +
                            " defined before this line)", part);
    // tinyobjloader refuses a forward reference too, with a message about "zero value" indices.
    if (index > 0 && static_cast<std::size_t>(index) > kind.defined)
        fail(line, "f", std::string(kind.name) + " index beyond the " + std::to_string(kind.defined) + " defined before this line", part);
}

}  // namespace

void validateObjText(const std::string& text) {
    Kind v{"vertex"}, vt{"texture coordinate"}, vn{"normal"};
    std::size_t lineNumber = 0, begin = 0;
    while (begin <= text.size()) {
        // A line ends at \n, \r\n or a lone \r, as tinyobjloader's safeGetline reads them.
        std::size_t end = text.find_first_of("\r\n", begin);
        if (end == std::string::npos) end = text.size();
        ++lineNumber;
        std::string_view line(text.data() + begin, end - begin);
        begin = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
        if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        const std::vector<std::string_view> t = tokens(line);
        if (t.empty()) continue;
        const std::string_view keyword = t[0];
        const std::size_t values = t.size() - 1;
        if (keyword == "v" || keyword == "vn" || keyword == "vt") {
            const bool ok = keyword == "v" ? (values == 3 || values == 4 || values == 6 || values == 7)
                          : keyword == "vn" ? values == 3
                                            : (values >= 1 && values <= 3);
            if (!ok)
                fail(lineNumber, keyword,
                     std::string("expected ") + (keyword == "v" ? "3 coordinates (or 4, or 3 and a colour)" : keyword == "vn" ? "3 coordinates" : "1 to 3 coordinates") +
                         ", found " + std::to_string(values),
                     line.substr(line.find(keyword) + keyword.size()));
            for (std::size_t i = 1; i < t.size(); ++i) checkCoordinate(lineNumber, keyword, t[i]);
            ++(keyword == "v" ? v : keyword == "vn" ? vn : vt).defined;
        } else if (keyword == "f") {
            if (values < 3) fail(lineNumber, "f", "a face needs at least 3 corners, found " + std::to_string(values), "");
            if (values > kMaxObjFaceCorners)
                fail(lineNumber, "f", "a face of " + std::to_string(values) + " corners; vkrt takes faces of up to " +
                                          std::to_string(kMaxObjFaceCorners) + " (triangulation time grows as the square of the corners)", "");
            for (std::size_t i = 1; i < t.size(); ++i) {
                const std::string_view corner = t[i];
                Kind* kinds[3] = {&v, &vt, &vn};
                std::size_t start = 0;
                for (int part = 0; part < 3 && start <= corner.size(); ++part) {
                    const std::size_t slash = std::min(corner.find('/', start), corner.size());
                    const std::string_view piece = corner.substr(start, slash - start);
                    if (piece.empty()) {
                        if (part == 0) fail(lineNumber, "f", "a corner without a vertex index", corner);
                    } else {
                        checkIndex(lineNumber, piece, *kinds[part]);
                    }
                    start = slash + 1;
                    if (slash == corner.size()) break;
                }
                if (std::count(corner.begin(), corner.end(), '/') > 2) fail(lineNumber, "f", "a corner has more than 3 indices", corner);
            }
        }
    }
}

}  // namespace vkrt
