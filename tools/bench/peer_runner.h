// The Embree peer (../shared/peer/): where to find it, how to build it, and running it on the same
// input in the same run so vkrt's figures can be quoted as ratios.
#pragma once

#include <optional>
#include <string>

namespace vkrt::bench {

// The peer's four output lines.
struct PeerFigures {
    double buildSeconds = 0.0, buildMtrisPerS = 0.0;
    double primaryMrays = 0.0, shadowMrays = 0.0, diffuseMrays = 0.0;
    std::size_t triangles = 0, primaryRays = 0, shadowRays = 0;
};

// The peer binary: `explicitPath` (--peer), else $VKRT_EMBREE_PEER; empty if neither names an
// executable file. With build = true, the peer is first built there (default /tmp/embree_peer)
// by ../shared/peer/build.sh.
std::string locatePeer(const std::string& explicitPath, bool build);

// Runs `peer source W H SPP THREADS quality`; nullopt (with the reason on stderr) if it fails or
// prints something unexpected.
std::optional<PeerFigures> runPeer(const std::string& peer, const std::string& source, int w, int h, int spp,
                                   int threads, const std::string& quality);

}  // namespace vkrt::bench
