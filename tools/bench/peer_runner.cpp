#include "peer_runner.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>

namespace vkrt::bench {

namespace {

std::string quoted(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string sharedDir() {
    if (const char* env = std::getenv("VKRT_SHARED"); env && *env) return env;
    return VKRT_DEFAULT_SHARED_DIR;
}

}  // namespace

std::string locatePeer(const std::string& explicitPath, bool build) {
    std::string path = explicitPath;
    if (path.empty())
        if (const char* env = std::getenv("VKRT_EMBREE_PEER"); env && *env) path = env;
    if (build) {
        if (path.empty()) path = "/tmp/embree_peer";
        const std::string cmd = quoted(sharedDir() + "/peer/build.sh") + " " + quoted(path) + " >&2";
        std::fprintf(stderr, "building the Embree peer: %s\n", cmd.c_str());
        if (std::system(cmd.c_str()) != 0) throw std::runtime_error("building the Embree peer failed: " + cmd);
    }
    if (path.empty() || access(path.c_str(), X_OK) != 0) return "";
    return path;
}

std::optional<PeerFigures> runPeer(const std::string& peer, const std::string& source, int w, int h, int spp,
                                   int threads, const std::string& quality) {
    const std::string cmd = quoted(peer) + " " + quoted(source) + " " + std::to_string(w) + " " + std::to_string(h) +
                            " " + std::to_string(spp) + " " + std::to_string(threads) + " " + quality;
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
    if (!pipe) {
        std::fprintf(stderr, "cannot run the peer: %s\n", cmd.c_str());
        return std::nullopt;
    }
    PeerFigures f;
    int seen = 0;
    char line[512];
    while (std::fgets(line, sizeof line, pipe.get())) {
        if (std::sscanf(line, "triangles %zu build_s %lf build_Mtris_per_s %lf", &f.triangles, &f.buildSeconds,
                        &f.buildMtrisPerS) == 3)
            seen |= 1;
        else if (std::sscanf(line, "primary rays %zu Mrays_per_s %lf", &f.primaryRays, &f.primaryMrays) == 2)
            seen |= 2;
        else if (std::sscanf(line, "shadow rays %zu Mrays_per_s %lf", &f.shadowRays, &f.shadowMrays) == 2)
            seen |= 4;
        else if (std::size_t n; std::sscanf(line, "diffuse rays %zu Mrays_per_s %lf", &n, &f.diffuseMrays) == 2)
            seen |= 8;
    }
    if (seen != 15) {
        std::fprintf(stderr, "the peer did not print its four lines: %s\n", cmd.c_str());
        return std::nullopt;
    }
    return f;
}

}  // namespace vkrt::bench
