// What `vkrt --watch --preview PORT` shows on its page (host/preview/): the latest image (each
// progressive pass too), a status line, and the last error until a render succeeds again.
#pragma once

#include <memory>
#include <string>

#include "image.h"
#include "preview_module.h"

namespace vkrt {

class WatchPreview {
public:
    // port < 0: no preview (every call does nothing); 0: any free port.
    WatchPreview(int port, std::string scene);
    bool enabled() const { return server_ != nullptr; }
    int port() const { return server_ ? server_->port() : -1; }

    void rendering(const std::string& status);                 // a render started
    void image(const Image& image, const std::string& status);  // a pass or a render finished
    void error(const std::string& message);                     // the render failed

private:
    void publish(const Image* image);

    std::unique_ptr<PreviewServer> server_;
    std::string scene_;
    long long images_ = 0;
    std::string status_, error_;
};

}  // namespace vkrt
