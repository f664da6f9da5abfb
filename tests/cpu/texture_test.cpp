// Texture lookup (RENDERING.md §7): bilinear between texel centres, wrap-around, v = 1 at the top
// row of the image; and the uv mappings of spheres and boxes.
#include <gtest/gtest.h>

#include "surface.h"
#include "texture.h"

namespace vkrt::cpu {
namespace {

std::uint32_t rgba(int r, int g, int b) { return std::uint32_t(r) | std::uint32_t(g) << 8 | std::uint32_t(b) << 16 | 0xff000000u; }

// 2x2: top row red, green; bottom row blue, white.
Texture checker() {
    Texture t;
    t.width = 2;
    t.height = 2;
    t.rgba8 = {rgba(255, 0, 0), rgba(0, 255, 0), rgba(0, 0, 255), rgba(255, 255, 255)};
    return t;
}

void expectColour(glm::vec3 got, glm::vec3 want) {
    EXPECT_NEAR(got.x, want.x, 1e-6f);
    EXPECT_NEAR(got.y, want.y, 1e-6f);
    EXPECT_NEAR(got.z, want.z, 1e-6f);
}

TEST(Texture, TexelCentresReturnTheTexel) {
    const Texture t = checker();
    expectColour(sampleTexture(t, {0.25f, 0.75f}), {1, 0, 0});  // top left
    expectColour(sampleTexture(t, {0.75f, 0.75f}), {0, 1, 0});  // top right
    expectColour(sampleTexture(t, {0.25f, 0.25f}), {0, 0, 1});  // bottom left
    expectColour(sampleTexture(t, {0.75f, 0.25f}), {1, 1, 1});  // bottom right
}

TEST(Texture, BilinearBetweenCentres) {
    const Texture t = checker();
    expectColour(sampleTexture(t, {0.5f, 0.75f}), {0.5f, 0.5f, 0});       // between red and green
    expectColour(sampleTexture(t, {0.5f, 0.5f}), {0.5f, 0.5f, 0.5f});     // all four
    expectColour(sampleTexture(t, {0.375f, 0.75f}), {0.75f, 0.25f, 0});  // a quarter of the way
}

TEST(Texture, WrapsAtTheEdges) {
    const Texture t = checker();
    // u = 0 is halfway between the last and the first column; so is u = 1; u = 1.25 is u = 0.25.
    expectColour(sampleTexture(t, {0.0f, 0.75f}), {0.5f, 0.5f, 0});
    expectColour(sampleTexture(t, {1.0f, 0.75f}), {0.5f, 0.5f, 0});
    expectColour(sampleTexture(t, {1.25f, 0.75f}), {1, 0, 0});
    expectColour(sampleTexture(t, {-0.75f, 1.75f}), {1, 0, 0});
}

TEST(Texture, BoxFaceFromTheSlabs) {
    const glm::vec3 lo(-1, -1, -1), hi(1, 1, 1);
    // From outside along -z: enters the z = +1 face.
    BoxFace f = boxFaceHit({0.2f, 0.3f, 5}, {0, 0, -1}, lo, hi);
    EXPECT_EQ(f.axis, 2);
    EXPECT_TRUE(f.maxSide);
    // From outside, steeply down onto the top.
    f = boxFaceHit({0.0f, 5.0f, 0.5f}, {0.1f, -1.0f, 0.0f}, lo, hi);
    EXPECT_EQ(f.axis, 1);
    EXPECT_TRUE(f.maxSide);
    // From inside, leaving through x = -1.
    f = boxFaceHit({0, 0, 0}, {-1.0f, 0.2f, 0.1f}, lo, hi);
    EXPECT_EQ(f.axis, 0);
    EXPECT_FALSE(f.maxSide);
}

}  // namespace
}  // namespace vkrt::cpu
