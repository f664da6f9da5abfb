#include "sample_count_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "bitmap_font.h"

namespace vkrt {

namespace {

constexpr int kScale = 2;                          // font pixels per glyph pixel
constexpr int kLine = (kGlyphHeight + 2) * kScale; // one legend line
constexpr int kMargin = 4;
const glm::vec3 kText(1.0f);

// Dark blue, purple, orange, yellow, white: brightness grows with the count, so the map reads in grey too.
glm::vec3 rampColour(float t) {
    const glm::vec3 stops[] = {{0.05f, 0.05f, 0.35f}, {0.55f, 0.1f, 0.6f}, {0.95f, 0.45f, 0.1f}, {1.0f, 0.9f, 0.2f}, {1.0f, 1.0f, 1.0f}};
    const float x = std::clamp(t, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(static_cast<int>(x), 3);
    return glm::mix(stops[i], stops[i + 1], x - static_cast<float>(i));
}

}  // namespace

Image sampleCountHeatMap(const std::vector<std::uint32_t>& counts, int width, int height) {
    std::uint32_t lo = std::numeric_limits<std::uint32_t>::max(), hi = 0;
    for (std::uint32_t c : counts)
        if (c > 0) lo = std::min(lo, c), hi = std::max(hi, c);
    if (hi == 0) lo = hi = 1;
    const double span = std::log2(static_cast<double>(hi) / lo);
    const auto position = [&](double count) { return span > 0.0 ? static_cast<float>(std::log2(count / lo) / span) : 0.0f; };

    const std::string title = "SAMPLES PER PIXEL";
    const int barWidth = std::clamp(width - 2 * kMargin - 8 * kScale * (kGlyphWidth + 1), 160, 320);
    const int legendWidth = std::max(barWidth + textWidth(std::to_string(hi), kScale), textWidth(title, kScale)) + 2 * kMargin;
    const int legendHeight = kMargin + 3 * kLine + kMargin;
    Image out(std::max(width, legendWidth), height + legendHeight);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint32_t c = counts[static_cast<std::size_t>(y) * width + x];
            out.at(x, y) = c > 0 ? rampColour(position(c)) : glm::vec3(0.0f);
        }
    int y = height + kMargin;
    drawText(out, kMargin, y, title, kScale, kText);
    y += kLine;
    for (int dx = 0; dx < barWidth; ++dx)
        for (int dy = 0; dy < kLine - kScale; ++dy) out.at(kMargin + dx, y + dy) = rampColour(static_cast<float>(dx) / (barWidth - 1));
    y += kLine;
    // Ticks: the two ends, and the powers of two between them where their labels fit.
    const auto xOf = [&](double count) { return kMargin + static_cast<int>(std::lround(position(count) * (barWidth - 1))); };
    const std::string loLabel = std::to_string(lo), hiLabel = std::to_string(hi);
    drawText(out, xOf(lo), y, loLabel, kScale, kText);
    int free = xOf(lo) + textWidth(loLabel, kScale) + 3 * kGlyphWidth * kScale;
    const int hiX = hi != lo ? xOf(hi) : 1 << 30;
    for (std::uint64_t p = 1; p < hi; p *= 2) {
        const std::string label = std::to_string(p);
        if (p <= lo || xOf(static_cast<double>(p)) < free || xOf(static_cast<double>(p)) + textWidth(label, kScale) + 3 * kGlyphWidth * kScale > hiX) continue;
        drawText(out, xOf(static_cast<double>(p)), y, label, kScale, kText);
        free = xOf(static_cast<double>(p)) + textWidth(label, kScale) + 3 * kGlyphWidth * kScale;
    }
    if (hi != lo) drawText(out, hiX, y, hiLabel, kScale, kText);
    return out;
}

}  // namespace vkrt
