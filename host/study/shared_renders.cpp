#include "shared_renders.h"

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>

namespace vkrt::study {

namespace {

// The commands rank 0 broadcasts while the reference is made.
enum class HalfCommand : std::uint32_t { Done = 0, Render = 1 };
struct HalfRequest {
    HalfCommand command = HalfCommand::Done;
    std::uint32_t seed = 0;
    std::int32_t rpp = 0;
};

template <class T>
void append(std::vector<std::byte>& bytes, const T* data, std::size_t count) {
    // resize and memcpy rather than insert: GCC 12 warns falsely (-Wstringop-overflow) on the insert.
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof(T) * count);
    if (count > 0) std::memcpy(bytes.data() + at, data, sizeof(T) * count);
}

// This rank's band of one half: its rows' floats.
std::vector<std::byte> renderBand(WorkSharing& sharing, StudyRenderer& renderer, const PreparedScene& scene, Device device,
                                  RenderOptions half) {
    const glm::ivec2 rows = partRows(half.height, sharing.rank() + 1, sharing.size());
    std::vector<std::byte> bytes;
    if (rows.x == rows.y) return bytes;  // more ranks than rows: nothing to do
    half.rows = rows;
    const TimedRender band = renderer.render(device, scene, half);
    append(bytes, &band.image.at(0, rows.x).x, static_cast<std::size_t>(rows.y - rows.x) * half.width * 3);
    return bytes;
}

std::vector<std::byte> requestBytes(const HalfRequest& request) {
    std::vector<std::byte> bytes;
    append(bytes, &request, 1);
    return bytes;
}

}  // namespace

std::vector<std::byte> packRender(const TimedRender& render) {
    std::vector<std::byte> bytes;
    const std::int32_t size[2] = {render.image.width, render.image.height};
    append(bytes, &render.seconds, 1);
    append(bytes, &render.meanRpp, 1);
    append(bytes, size, 2);
    append(bytes, &render.image.pixels[0].x, render.image.pixels.size() * 3);
    return bytes;
}

TimedRender unpackRender(const std::vector<std::byte>& bytes) {
    TimedRender render;
    std::int32_t size[2] = {0, 0};
    constexpr std::size_t header = 2 * sizeof(double) + sizeof size;
    if (bytes.size() < header) throw std::runtime_error("sweep: a rank sent a render of " + std::to_string(bytes.size()) + " bytes");
    std::memcpy(&render.seconds, bytes.data(), sizeof(double));
    std::memcpy(&render.meanRpp, bytes.data() + sizeof(double), sizeof(double));
    std::memcpy(size, bytes.data() + 2 * sizeof(double), sizeof size);
    render.image = Image(size[0], size[1]);
    if (bytes.size() != header + render.image.pixels.size() * sizeof(glm::vec3))
        throw std::runtime_error("sweep: a rank sent a render whose size does not match its pixels");
    std::memcpy(&render.image.pixels[0].x, bytes.data() + header, render.image.pixels.size() * sizeof(glm::vec3));
    return render;
}

HalfRenderer sharedHalfRenderer(WorkSharing& sharing, StudyRenderer& renderer, const PreparedScene& scene, Device device) {
    return [&sharing, &renderer, &scene, device](const RenderOptions& half) {
        const auto start = std::chrono::steady_clock::now();
        std::vector<std::byte> request = requestBytes({HalfCommand::Render, half.seed, half.samplesPerPixel});
        sharing.broadcast(request);
        const std::vector<std::vector<std::byte>> bands = sharing.gather(renderBand(sharing, renderer, scene, device, half));
        TimedRender whole;
        whole.image = Image(half.width, half.height);
        for (int r = 0; r < sharing.size(); ++r) {
            const glm::ivec2 rows = partRows(half.height, r + 1, sharing.size());
            const std::vector<std::byte>& band = bands[static_cast<std::size_t>(r)];
            if (band.size() != static_cast<std::size_t>(rows.y - rows.x) * half.width * sizeof(glm::vec3))
                throw std::runtime_error("sweep: rank " + std::to_string(r) + " sent a reference band of the wrong size");
            if (!band.empty()) std::memcpy(&whole.image.at(0, rows.x).x, band.data(), band.size());
        }
        whole.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return whole;
    };
}

void serveHalves(WorkSharing& sharing, StudyRenderer& renderer, const PreparedScene& scene, Device device,
                 const RenderOptions& spec) {
    for (;;) {
        std::vector<std::byte> bytes;
        sharing.broadcast(bytes);
        HalfRequest request;
        if (bytes.size() != sizeof request) throw std::runtime_error("sweep: rank 0 sent a malformed request");
        std::memcpy(&request, bytes.data(), sizeof request);
        if (request.command == HalfCommand::Done) return;
        RenderOptions half = spec;
        half.seed = request.seed;
        half.samplesPerPixel = request.rpp;
        sharing.gather(renderBand(sharing, renderer, scene, device, half));
    }
}

void endHalves(WorkSharing& sharing) {
    std::vector<std::byte> done = requestBytes({HalfCommand::Done, 0, 0});
    sharing.broadcast(done);
}

void renderShared(WorkSharing& sharing, std::size_t count, const std::function<TimedRender(std::size_t)>& render,
                  const std::function<void(std::size_t, const TimedRender&)>& received) {
    const auto ranks = static_cast<std::size_t>(sharing.size());
    const auto rank = static_cast<std::size_t>(sharing.rank());
    for (std::size_t first = 0; first < count; first += ranks) {
        std::vector<std::byte> mine;
        if (first + rank < count) mine = packRender(render(first + rank));
        const std::vector<std::vector<std::byte>> all = sharing.gather(mine);
        if (rank != 0) continue;
        for (std::size_t r = 0; r < ranks && first + r < count; ++r) received(first + r, unpackRender(all[r]));
    }
}

}  // namespace vkrt::study
