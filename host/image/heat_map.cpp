#include "heat_map.h"

#include <algorithm>

#include "bitmap_font.h"

namespace vkrt {

namespace {

constexpr int kScale = 2;                              // font pixels per glyph pixel
constexpr int kLine = (kGlyphHeight + 2) * kScale;     // one text line with its gap
constexpr int kMargin = 4;
constexpr int kStepWidth = 6;                          // colour-bar pixels per 8-bit step
const glm::vec3 kText(0.85f);

}  // namespace

glm::vec3 differenceColour(int steps) {
    if (steps <= 0) return glm::vec3(0.0f);
    const float s = std::min(steps, kHeatMapFullScale) / float(kHeatMapFullScale);
    return {0.25f + 0.75f * std::min(1.0f, 2 * s), std::max(0.0f, 2 * s - 1), 0.0f};
}

Image withDifferenceLegend(const Image& map, const std::vector<LegendSwatch>& swatches) {
    const int barWidth = (kHeatMapFullScale + 1) * kStepWidth;
    const std::string title = "DIFFERENCE IN /255";
    int legendWidth = std::max(barWidth + textWidth("16+", kScale), textWidth(title, kScale));
    for (const LegendSwatch& s : swatches) legendWidth = std::max(legendWidth, kLine + textWidth(s.second, kScale));
    legendWidth += 2 * kMargin;
    // title, bar, tick labels, then one line per swatch
    const int legendHeight = kMargin + kLine + kLine + kLine + static_cast<int>(swatches.size()) * kLine + kMargin;

    Image out(std::max(map.width, legendWidth), map.height + legendHeight);
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) out.at(x, y) = map.at(x, y);

    int y = map.height + kMargin;
    drawText(out, kMargin, y, title, kScale, kText);
    y += kLine;
    for (int step = 0; step <= kHeatMapFullScale; ++step)
        for (int dy = 0; dy < kLine - kScale; ++dy)
            for (int dx = 0; dx < kStepWidth; ++dx) out.at(kMargin + step * kStepWidth + dx, y + dy) = differenceColour(step);
    y += kLine;
    for (int tick : {0, 2, 4, 8}) drawText(out, kMargin + tick * kStepWidth, y, std::to_string(tick), kScale, kText);
    drawText(out, kMargin + kHeatMapFullScale * kStepWidth, y, "16+", kScale, kText);
    y += kLine;
    for (const LegendSwatch& s : swatches) {
        for (int dy = 0; dy < kLine - kScale; ++dy)
            for (int dx = 0; dx < kLine - kScale; ++dx) out.at(kMargin + dx, y + dy) = s.first;
        drawText(out, kMargin + kLine, y + kScale / 2, s.second, kScale, kText);
        y += kLine;
    }
    return out;
}

}  // namespace vkrt
