// A parsed XML scene file that can say on which line any node sits (pugixml only reports byte
// offsets, so the newline positions of the original buffer are kept alongside the DOM).
#pragma once

#include <memory>
#include <string>

#include <pugixml.hpp>

#include "source_text.h"

namespace vkrt {

class XmlSource {
public:
    // `text` is the file's content (readSourceFile). Throws SceneError for malformed XML.
    XmlSource(std::string path, const std::string& text);

    const std::string& path() const { return path_; }
    pugi::xml_node root() const { return document_->document_element(); }
    // 1-based line of the node's start tag (attributes report their element's line).
    int lineOf(pugi::xml_node node) const;
    int lineOfOffset(std::ptrdiff_t offset) const;

private:
    std::string path_;
    std::unique_ptr<pugi::xml_document> document_;  // pugi documents cannot be moved in all builds
    LineIndex lines_;
};

}  // namespace vkrt
