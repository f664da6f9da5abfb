#include "preview_module.h"

#include <stdexcept>

#include <dlfcn.h>

#include "module_loader.h"

namespace vkrt {

namespace {

const preview::Api& previewApi() {
    return moduleTable<preview::Api>({"libvkrt_preview.so", "VKRT_PREVIEW_MODULE", "vkrt_preview_api", RTLD_LOCAL},
                                     preview::kApiVersion, "--preview: the preview page's HTTP server");
}

}  // namespace

PreviewServer::PreviewServer(int port) : api_(previewApi()), port_(port) {
    std::string error;
    server_ = api_.start(&port_, error);
    if (!server_) throw std::runtime_error("--preview " + std::to_string(port) + ": " + error);
}

PreviewServer::~PreviewServer() { api_.stop(server_); }

void PreviewServer::publish(const std::vector<unsigned char>& png, const std::string& statusJson) {
    api_.publish(server_, png, statusJson);
}

}  // namespace vkrt
