// The preview server of `vkrt --watch --preview PORT`: a page on localhost showing the latest image
// and the last error, refreshed as renders finish. Built as a module of its own (libvkrt_preview.so,
// with cpp-httplib and the TLS and compression libraries Debian builds it with), loaded only when
// --preview is given (preview_module.h), so no other run maps them (docs/STARTUP.md).
//
// A table of functions behind one extern "C" entry point, as host/mpi/mpi_api.h.
#pragma once

#include <string>
#include <vector>

namespace vkrt::preview {

inline constexpr int kApiVersion = 1;

struct Api {
    int version;
    // Serves on 127.0.0.1:port (0: a free port, written to *port) from a thread of its own; null with
    // `error` when the port cannot be had.
    void* (*start)(int* port, std::string& error);
    // The image (PNG bytes) and the status (a JSON object) the page shows from now on.
    void (*publish)(void* server, const std::vector<unsigned char>& png, const std::string& statusJson);
    // Stops serving and frees the server.
    void (*stop)(void* server);
};

}  // namespace vkrt::preview

extern "C" const vkrt::preview::Api* vkrt_preview_api();
