// A parsed XML scene file that can say on which line any node sits (pugixml only reports byte
// offsets, so the newline positions of the original buffer are kept alongside the DOM).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pugixml.hpp>

namespace vkrt {

class XmlSource {
public:
    // Throws SceneError for a missing, unreadable or malformed file.
    explicit XmlSource(std::string path);

    const std::string& path() const { return path_; }
    pugi::xml_node root() const { return document_->document_element(); }
    // 1-based line of the node's start tag (attributes report their element's line).
    int lineOf(pugi::xml_node node) const;
    int lineOfOffset(std::ptrdiff_t offset) const;

private:
    std::string path_;
    std::unique_ptr<pugi::xml_document> document_;  // pugi documents cannot be moved in all builds
    std::vector<std::ptrdiff_t> newlineOffsets_;
};

}  // namespace vkrt
