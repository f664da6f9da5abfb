// A sweep's renders shared among the ranks of a WorkSharing (work_sharing.h):
//  - the reference's halves by rows: rank 0 asks, every rank renders its band of rows
//    (partRows(height, rank + 1, ranks)), rank 0 gathers the bands. A pixel is computed as in the
//    whole image (render_options.h), so the reference is the one-process reference, bit for bit,
//    and the cache holds the same files;
//  - the sweep's settings round by round: in round k rank r renders setting k * ranks + r and
//    rank 0 receives the images in setting order, so the rows, CSV and report come out in the
//    one-process order.
// A rank's error ends the job (the application aborts every rank), so no rank waits for ever.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "reference_cache.h"
#include "study_renderer.h"
#include "work_sharing.h"

namespace vkrt::study {

// A render as bytes (its seconds, size and float pixels) and back.
std::vector<std::byte> packRender(const TimedRender& render);
TimedRender unpackRender(const std::vector<std::byte>& bytes);

// Rank 0's HalfRenderer: each half rendered by every rank in bands, gathered here.
HalfRenderer sharedHalfRenderer(WorkSharing& sharing, StudyRenderer& renderer, const PreparedScene& scene, Device device);
// The other ranks: render bands of the halves rank 0 asks for until it says the reference is done.
void serveHalves(WorkSharing& sharing, StudyRenderer& renderer, const PreparedScene& scene, Device device,
                 const RenderOptions& spec);
// Rank 0: the reference is done (loaded or rendered); the other ranks stop serving.
void endHalves(WorkSharing& sharing);

// Renders settings [0, count) round by round, render(i) computing setting i on this rank;
// `received(i, render)` is called on rank 0 for every setting, in order.
void renderShared(WorkSharing& sharing, std::size_t count, const std::function<TimedRender(std::size_t)>& render,
                  const std::function<void(std::size_t, const TimedRender&)>& received);

// The single process's WorkSharing: rank 0 of 1.
class NoSharing : public WorkSharing {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    void broadcast(std::vector<std::byte>&) override {}
    std::vector<std::vector<std::byte>> gather(const std::vector<std::byte>& mine) override { return {mine}; }
};

}  // namespace vkrt::study
