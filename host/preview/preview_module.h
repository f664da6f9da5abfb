// The preview server, through its module (preview_api.h): found and loaded on first use like
// OpenImageIO's codec (host/modules/module_loader.h). RAII over one server.
#pragma once

#include <string>
#include <vector>

#include "preview_api.h"

namespace vkrt {

class PreviewServer {
public:
    // Loads the module and starts serving on 127.0.0.1:port (0: any free port); throws
    // std::runtime_error naming the port, or the module candidates tried.
    explicit PreviewServer(int port);
    ~PreviewServer();
    PreviewServer(const PreviewServer&) = delete;
    PreviewServer& operator=(const PreviewServer&) = delete;

    int port() const { return port_; }
    // An empty `png` keeps the image shown.
    void publish(const std::vector<unsigned char>& png, const std::string& statusJson);

private:
    const preview::Api& api_;
    int port_;
    void* server_ = nullptr;
};

}  // namespace vkrt
