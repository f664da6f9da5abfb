#include "watch_preview.h"

#include <nlohmann/json.hpp>

namespace vkrt {

WatchPreview::WatchPreview(int port, std::string scene) : scene_(std::move(scene)) {
    if (port >= 0) server_ = std::make_unique<PreviewServer>(port);
}

void WatchPreview::rendering(const std::string& status) {
    status_ = status;
    publish(nullptr);
}

void WatchPreview::image(const Image& image, const std::string& status) {
    status_ = status;
    error_.clear();
    ++images_;
    publish(&image);
}

void WatchPreview::error(const std::string& message) {
    status_ = "the last render failed; the image is the one before it";
    error_ = message;
    publish(nullptr);
}

void WatchPreview::publish(const Image* image) {
    if (!server_) return;
    // A path or message that is not UTF-8 (a file name in another encoding) is shown with U+FFFD
    // in its place: JSON holds only UTF-8, and a throwing dump would end the watch.
    const nlohmann::json status = {{"image", images_}, {"status", status_}, {"error", error_}, {"scene", scene_}};
    server_->publish(image ? encodePng(*image) : std::vector<unsigned char>{}, status.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

}  // namespace vkrt
