#include "bitmap_font.h"

#include <cctype>
#include <cstring>

namespace vkrt {

namespace {

struct Glyph {
    char c;
    const char* rows;  // 5 rows of 3 pixels, top first: '#' drawn
};

// Each glyph fits 3x5 so that a 64-pixel-wide image still has room for a legend line.
constexpr Glyph kGlyphs[] = {
    {'0', "####.##.##.####"}, {'1', ".#.##..#..#.###"}, {'2', "###..#####..###"}, {'3', "###..####..####"},
    {'4', "#.##.####..#..#"}, {'5', "####..###..####"}, {'6', "####..####.####"}, {'7', "###..#..#..#..#"},
    {'8', "####.#####.####"}, {'9', "####.####..####"}, {'A', ".#.#.#####.##.#"}, {'B', "##.#.###.#.###."},
    {'C', "####..#..#..###"}, {'D', "##.#.##.##.###."}, {'E', "####..####..###"}, {'F', "####..####..#.."},
    {'G', "####..#.##.####"}, {'H', "#.##.####.##.##"}, {'I', "###.#..#..#.###"}, {'J', "..#..#..##.####"},
    {'K', "#.##.###.#.##.#"}, {'L', "#..#..#..#..###"}, {'M', "#.########.##.#"}, {'N', "##.#.##.##.##.#"},
    {'O', "####.##.##.####"}, {'P', "####.#####..#.."}, {'Q', "####.##.####..#"}, {'R', "####.###.#.##.#"},
    {'S', "####..###..####"}, {'T', "###.#..#..#..#."}, {'U', "#.##.##.##.####"}, {'V', "#.##.##.##.#.#."},
    {'W', "#.##.########.#"}, {'X', "#.##.#.#.#.##.#"}, {'Y', "#.##.#.#..#..#."}, {'Z', "###..#.#.#..###"},
    {'/', "..#..#.#.#..#.."}, {'+', "....#.###.#...."}, {'-', "......###......"}, {'.', "............#.."},
    {':', "....#.....#...."}, {'<', "..#.#.#...#...#"}, {'>', "#...#...#.#.#.."}, {'=', "...###...###..."},
    {'(', ".#.#..#..#...#."}, {')', ".#...#..#..#.#."}, {',', ".........#.#..."},
};

const char* rowsOf(char c) {
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const Glyph& g : kGlyphs)
        if (g.c == upper && std::strlen(g.rows) == kGlyphWidth * kGlyphHeight) return g.rows;
    return nullptr;
}

}  // namespace

int textWidth(const std::string& text, int scale) {
    return text.empty() ? 0 : static_cast<int>(text.size()) * (kGlyphWidth + 1) * scale - scale;
}

void drawText(Image& image, int x, int y, const std::string& text, int scale, glm::vec3 colour) {
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char* rows = rowsOf(text[k]);
        if (!rows) continue;
        const int left = x + static_cast<int>(k) * (kGlyphWidth + 1) * scale;
        for (int gy = 0; gy < kGlyphHeight; ++gy)
            for (int gx = 0; gx < kGlyphWidth; ++gx) {
                if (rows[gy * kGlyphWidth + gx] != '#') continue;
                for (int sy = 0; sy < scale; ++sy)
                    for (int sx = 0; sx < scale; ++sx) {
                        const int px = left + gx * scale + sx, py = y + gy * scale + sy;
                        if (px >= 0 && py >= 0 && px < image.width && py < image.height) image.at(px, py) = colour;
                    }
            }
    }
}

}  // namespace vkrt
