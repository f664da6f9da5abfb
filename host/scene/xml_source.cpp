#include "xml_source.h"

#include <algorithm>

#include "diagnostics.h"

namespace vkrt {

namespace {

// The text at a parse-error offset, so the message shows what the parser choked on.
std::string snippetAt(const std::string& text, std::ptrdiff_t offset) {
    if (offset < 0 || static_cast<std::size_t>(offset) >= text.size()) return "end of file";
    std::size_t end = text.find('\n', static_cast<std::size_t>(offset));
    if (end == std::string::npos) end = text.size();
    return text.substr(static_cast<std::size_t>(offset), std::min<std::size_t>(end - offset, 40));
}

}  // namespace

XmlSource::XmlSource(std::string path, const std::string& text)
    : path_(std::move(path)), document_(std::make_unique<pugi::xml_document>()), lines_(text) {
    // encoding_utf8: the files are ASCII/UTF-8, and a fixed encoding keeps pugixml's offsets equal
    // to offsets in `text` (conversion from UTF-16 would shift them).
    const pugi::xml_parse_result result =
        document_->load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!result) {
        const std::string snippet = snippetAt(text, result.offset);
        // A file cut short (an editor's save caught half-way, a missing close tag) has no text to show.
        throw SceneError({path_, lineOfOffset(result.offset), "xml",
                          std::string("malformed XML (") + result.description() + ") at" + (snippet.empty() ? " the end of the file" : ""),
                          snippet});
    }
    if (!root()) throw SceneError({path_, 1, "xml", "the file has no root element", ""});
}

int XmlSource::lineOfOffset(std::ptrdiff_t offset) const { return lines_.lineOf(offset); }

int XmlSource::lineOf(pugi::xml_node node) const {
    const std::ptrdiff_t offset = node.offset_debug();
    return offset < 0 ? 0 : lineOfOffset(offset);
}

}  // namespace vkrt
