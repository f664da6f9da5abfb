// libvkrt_preview.so: preview_api.h's table, implemented with cpp-httplib.
#include <memory>
#include <mutex>
#include <thread>

#include <httplib.h>

#include "preview_api.h"

namespace vkrt::preview {
namespace {

// The page: the image at its own size, the status line under it and the last error in red. It
// asks for /status twice a second and reloads the image when the status says a new one is there
// (the status's "image" counter), so a browser left open follows every render.
constexpr const char* kPage = R"(<!doctype html>
<html><head><meta charset="utf-8"><title>vkrt preview</title>
<style>
body { margin: 0; background: #202020; color: #e0e0e0; font: 14px monospace; }
#image { display: block; image-rendering: pixelated; }
#status { padding: 6px 8px; white-space: pre-wrap; }
#error { padding: 0 8px; color: #ff6060; white-space: pre-wrap; }
</style></head>
<body>
<img id="image" src="/image.png?0" alt="no image yet">
<div id="status">waiting for the first render</div>
<div id="error"></div>
<script>
let shown = -1;
async function refresh() {
  try {
    const s = await (await fetch('/status', {cache: 'no-store'})).json();
    if (s.image !== shown) {
      shown = s.image;
      document.getElementById('image').src = '/image.png?' + s.image;
    }
    document.getElementById('status').textContent = s.status;
    document.getElementById('error').textContent = s.error;
    document.title = 'vkrt: ' + s.scene;
  } catch (e) {
    document.getElementById('status').textContent = 'vkrt is not running (' + e + ')';
  }
}
refresh();
setInterval(refresh, 500);
</script>
</body></html>
)";

// Limits that keep the page's server small whatever a client sends: it serves three GETs, so a
// request body is refused (413) past a few KiB; a client that sends nothing for 2 s is dropped; and
// 32 worker threads outlast a handful of slow clients.
constexpr std::size_t kMaxRequestBody = 4096;
constexpr time_t kReadTimeoutSeconds = 2;
constexpr std::size_t kWorkerThreads = 32;

struct Server {
    httplib::Server http;
    int port = 0;
    std::thread thread;
    std::mutex mutex;  // guards png and status
    std::vector<unsigned char> png;
    std::string status = R"({"image": 0, "status": "waiting for the first render", "error": "", "scene": ""})";
};

void* start(int* port, std::string& error) {
    auto server = std::make_unique<Server>();
    Server* s = server.get();
    s->http.new_task_queue = [] { return new httplib::ThreadPool(kWorkerThreads); };
    s->http.set_payload_max_length(kMaxRequestBody);
    s->http.set_read_timeout(kReadTimeoutSeconds);
    s->http.set_keep_alive_timeout(kReadTimeoutSeconds);
    // DNS rebinding: a web site whose name resolves to 127.0.0.1 could read the page from the
    // user's browser. Only requests addressed to this server by its loopback name pass, and
    // cross-site fetches (an Origin other than the page's own) are refused.
    s->http.set_pre_routing_handler([s](const httplib::Request& req, httplib::Response& res) {
        const std::string port = std::to_string(s->port);
        const std::string host = req.get_header_value("Host");
        const std::string origin = req.get_header_value("Origin");
        const bool hostOk = host == "127.0.0.1:" + port || host == "localhost:" + port;
        const bool originOk = origin.empty() || origin == "http://127.0.0.1:" + port || origin == "http://localhost:" + port;
        if (hostOk && originOk) return httplib::Server::HandlerResponse::Unhandled;
        res.status = 403;
        res.set_content("vkrt preview: only http://127.0.0.1:" + port + "/ is served\n", "text/plain");
        return httplib::Server::HandlerResponse::Handled;
    });
    s->http.Get("/", [](const httplib::Request&, httplib::Response& res) { res.set_content(kPage, "text/html; charset=utf-8"); });
    s->http.Get("/status", [s](const httplib::Request&, httplib::Response& res) {
        std::lock_guard lock(s->mutex);
        res.set_header("Cache-Control", "no-store");
        res.set_content(s->status, "application/json");
    });
    s->http.Get("/image.png", [s](const httplib::Request&, httplib::Response& res) {
        std::lock_guard lock(s->mutex);
        res.set_header("Cache-Control", "no-store");
        if (s->png.empty()) {
            res.status = 404;
            res.set_content("no image yet", "text/plain");
            return;
        }
        res.set_content(reinterpret_cast<const char*>(s->png.data()), s->png.size(), "image/png");
    });
    // Localhost only: the page shows what is being rendered to whoever can reach it.
    if (*port == 0) {
        *port = s->http.bind_to_any_port("127.0.0.1");
        if (*port <= 0) {
            error = "cannot listen on any port of 127.0.0.1";
            return nullptr;
        }
    } else if (!s->http.bind_to_port("127.0.0.1", *port)) {
        error = "cannot listen on 127.0.0.1:" + std::to_string(*port) + " (in use by another program?)";
        return nullptr;
    }
    s->port = *port;
    s->thread = std::thread([s] { s->http.listen_after_bind(); });
    return server.release();
}

void publish(void* server, const std::vector<unsigned char>& png, const std::string& statusJson) {
    auto* s = static_cast<Server*>(server);
    std::lock_guard lock(s->mutex);
    if (!png.empty()) s->png = png;
    s->status = statusJson;
}

void stop(void* server) {
    auto* s = static_cast<Server*>(server);
    s->http.stop();
    if (s->thread.joinable()) s->thread.join();
    delete s;
}

constexpr Api kApi{kApiVersion, start, publish, stop};

}  // namespace
}  // namespace vkrt::preview

extern "C" const vkrt::preview::Api* vkrt_preview_api() { return &vkrt::preview::kApi; }
