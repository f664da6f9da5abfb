#include "diagnostics.h"

#include <utility>

namespace vkrt {

namespace {

// A value may be element text spanning lines, or a whole paragraph of garbage, and a problem may
// quote a library's multi-line message: keep the message on one line. Values are also shortened
// past kMaxChars, which is long enough for any real path but not for a pasted paragraph.
std::string oneLine(const std::string& value, std::size_t kMaxChars) {
    std::string flat;
    bool lastWasSpace = false;
    for (char c : value) {
        const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (space && lastWasSpace) continue;
        flat += space ? ' ' : c;
        lastWasSpace = space;
    }
    while (!flat.empty() && flat.back() == ' ') flat.pop_back();
    if (!flat.empty() && flat.front() == ' ') flat.erase(0, 1);  // runs were collapsed to one space
    if (flat.size() > kMaxChars) flat = flat.substr(0, kMaxChars) + "...";
    return flat;
}

}  // namespace

std::string Issue::message() const {
    std::string text = file + ":" + std::to_string(line);
    if (column > 0) text += ":" + std::to_string(column);
    text += ": " + element + ": " + oneLine(problem, std::string::npos);
    if (!value.empty()) text += " '" + oneLine(value, 240) + "'";
    return text;
}

SceneError::SceneError(Issue issue) : std::runtime_error(issue.message()), issue_(std::move(issue)) {}

void Diagnostics::warn(Issue issue) {
    if (strict_) throw SceneError(std::move(issue));
    warnings_.push_back(std::move(issue));
}

std::vector<std::string> Diagnostics::messages() const {
    std::vector<std::string> lines;
    lines.reserve(warnings_.size());
    for (const Issue& issue : warnings_) lines.push_back(issue.message());
    return lines;
}

}  // namespace vkrt
