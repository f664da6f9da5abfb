// `vkrt check SCENE IMAGE`: is someone's image of a scene the same picture as vkrt's render of it?
// The image is tested pixel by pixel against vkrt's CPU reference (its mean and per-pixel sample
// variance) and, when it differs, against the same reference transformed by each common mistake
// of a course ray tracer (flipped rows, gamma, half-pixel offset...), to name the one that
// explains the difference. The renders a mistake needs (another background, a light left out)
// are made by check_command.cpp; everything here works on images only.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "image.h"

namespace vkrt {

// check's reference: 64 jittered rpp unless -r says otherwise. The test accounts for the
// reference's noise, so fewer samples give a more lenient test, not a wrong one; 64 keeps a
// 250x250 course scene under a few seconds on two cores.
inline constexpr int kCheckReferenceRpp = 64;

// vkrt's render of the scene at the image's size.
struct CheckReference {
    Image mean;            // linear radiance, the pixel means
    Image sampleVariance;  // per pixel and channel, the unbiased variance of one sample
    int rpp = 1;
};

struct PixelTestOptions {
    // Family-wise rate of false failures over all values (Sidak-corrected per value, as z_test.h).
    double alpha = 0.01;
    // The verdict: the same picture when at least this fraction of pixels pass. 1% leaves room for
    // what a correct ray tracer may do differently without being wrong: where its float rounding
    // tips a ray at a silhouette or shadow edge, or a self-intersection epsilon of its own.
    double requiredFraction = 0.99;
    // Allowed on top of the noise, in [0,1] units: 8-bit output truncates (vkrt, the course) or
    // rounds (most image libraries), which is up to 1/255 apart, and an independent ray tracer's
    // float arithmetic moves a flat area by about as much again.
    double slack = 2.0 / 255.0;
    // 8-bit images hold the display values: the reference is clamped to [0,1] as it is written.
    bool clampReference = true;
};

struct PixelTestResult {
    std::size_t pixels = 0, passed = 0;  // a pixel passes when all three channels do
    double zLimit = 0.0;                 // the per-value limit in standard errors
    double meanSignedDifference = 0.0;   // yours - vkrt over all values, [0,1] units
    bool same = false;                   // passedFraction() >= requiredFraction
    double passedFraction() const { return pixels == 0 ? 1.0 : static_cast<double>(passed) / static_cast<double>(pixels); }
};

// Per pixel and channel: |yours - vkrt| - slack must be within zLimit standard errors, where the
// variance is s^2 (1 + 1/rpp): the reference mean's own, plus one sample's for `yours`, whose
// sample count is unknown (a course ray tracer without anti-aliasing shoots one ray per pixel;
// more samples only make it closer). Throws std::invalid_argument when the sizes differ.
PixelTestResult testPixels(const Image& yours, const CheckReference& reference, const PixelTestOptions& options = {});

// A common mistake, expressed as what it does to vkrt's correct image: `yours` is tested against
// `apply(reference)`.
struct Mistake {
    std::string name;         // "flipped vertically"
    std::string explanation;  // what to look for in one's code
    CheckReference (*apply)(const CheckReference&);
    bool swapsAxes = false;   // only for square images (a swapped image of another shape has another size)
};

// The mistakes that change an image without re-rendering: flips, rotations and a transposition
// (square images only for those that swap the axes), gamma/sRGB encoding applied or undone, and
// half-pixel offsets of the pixel centres.
const std::vector<Mistake>& imageMistakes();

// Transforms, exposed for the tests.
Image flippedVertically(const Image& image);
Image mirrored(const Image& image);
Image transposed(const Image& image);
float srgbEncode(float linear);  // IEC 61966-2-1
float srgbDecode(float encoded);

// The difference map `vkrt check` writes: black where the images agree within the slack, grey
// (kWithinNoiseGrey) where they differ within vkrt's noise, and differenceColour (heat_map.h) of
// the 8-bit difference where a pixel fails.
inline constexpr float kWithinNoiseGrey = 0.3f;
Image checkMap(const Image& yours, const CheckReference& reference, const PixelTestOptions& options = {});

// The most common 8-bit colour among the pixels that fail (for the "wrong background" mistake:
// a background fills whole regions with one colour). (0,0,0) with count 0 when none fail.
struct ColourCount {
    glm::vec3 colour{0.0f};
    std::size_t count = 0;
};
ColourCount commonFailingColour(const Image& yours, const CheckReference& reference, const PixelTestOptions& options = {});

// The fraction of failing pixels where vkrt's image is black (every channel below 1/255) and
// yours is not: light where the course's shading has none, as an ambient term adds.
double fractionFailingWhereReferenceBlack(const Image& yours, const CheckReference& reference,
                                          const PixelTestOptions& options = {});

}  // namespace vkrt
