// Error figures of a buffer against the exact reference (conventions.md, "Figures and
// errors"), and a heat map of where they differ.
//
// The FIRST image is the reference: `shadowlab compare A.exr B.exr` measures B against A.
// Pixels are compared where the reference has hit = 1; the test image's hit channel is not
// consulted, so a technique that loses geometry is charged for it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "shading/image_io.h"

namespace shadowlab {

struct CompareOptions {
    std::string channel = "V";
    // A value >= threshold counts as lit, below it as shadowed, for the classification
    // into false shadow and false light (conventions.md: for binary shadows).
    float litThreshold = 0.5f;
    // |error| mapped to full colour intensity in the heat map.
    float heatMapFullScale = 1.0f;
    // Umbra errors of soft shadows (docs/soft-shadows.md): an umbra is V < umbraThreshold,
    // a fully lit region V > 1 - umbraThreshold; the test lights the reference's umbra when
    // above umbraTolerance, over-estimates the umbra where its V < umbraThreshold and the
    // reference's is above umbraTolerance, and shadows full light below 1 - umbraTolerance.
    float umbraThreshold = 0.02f;
    float umbraTolerance = 0.1f;
    // The finer figure beside it: the full umbra, where no ray of the reference reaches the
    // light (V < fullUmbraThreshold, below one of reference-soft's 1024 rays), lit by the
    // test above fullUmbraTolerance, a fiftieth of the light (conventions.md).
    float fullUmbraThreshold = 0.001f;
    float fullUmbraTolerance = 0.02f;
};

struct ErrorFigures {
    std::string channel;
    uint64_t pixels = 0;         // pixels with hit = 1 in the reference
    // error = reference - test over those pixels. NaN in either input makes these NaN.
    double rms = 0.0;
    double meanAbs = 0.0;
    double maxAbs = 0.0;
    // Radiance images only (frame/score.h): the RMS of the display luminance, Y of the image
    // tone mapped for display (shading/tonemap.h, Reinhard at exposure 0), as an image's
    // error is seen (the RMS DeCoro and Rusinkiewicz report); empty for V.
    std::optional<double> rmsDisplay;
    // FLIP (shading/flip.h) of the test's shaded image against the reference's, both tone
    // mapped for display as rmsDisplay's luminance is, at 67 pixels per degree: the mean of its
    // error map over the reference's hit pixels, in [0, 1] (frame/score.h, flipFigure()).
    // Empty where the shaded images were not at hand (compare of EXR files without R, G, B).
    std::optional<double> flipMean;
    // True if every compared value of both images is exactly 0 or 1 (hard shadows), where
    // the classification below is the natural figure; it is computed in any case.
    bool binary = true;
    uint64_t falseShadow = 0;    // lit in the reference, shadowed in the test (acne)
    uint64_t falseLight = 0;     // shadowed in the reference, lit in the test (leaks)
    uint64_t misclassified() const { return falseShadow + falseLight; }
    // Umbra errors (CompareOptions), the gross errors of soft shadows: light in the
    // reference's umbra, and the reverse, umbra where the reference sees the light (the
    // error of smoothies, which over-estimate the umbra); and shadow in full light.
    uint64_t umbraPixels = 0;    // reference V < umbraThreshold
    uint64_t litPixels = 0;      // reference V > 1 - umbraThreshold
    uint64_t umbraLit = 0;       // of umbraPixels, test V > umbraTolerance
    uint64_t umbraOver = 0;      // test V < umbraThreshold, reference V > umbraTolerance
    uint64_t litShadowed = 0;    // of litPixels, test V < 1 - umbraTolerance
    uint64_t fullUmbraPixels = 0;   // reference V < fullUmbraThreshold
    uint64_t fullUmbraLit = 0;      // of fullUmbraPixels, test V > fullUmbraTolerance ("umbra lit 0.02")
    // False for figures read from a JSON written before "umbra lit 0.02" existed: the two
    // counts above are then not recorded, and are shown and written as such.
    bool fullUmbraRecorded = true;
    uint64_t umbraErrors() const { return umbraLit + umbraOver; }
    double percentOfPixels(uint64_t count) const {
        return pixels == 0 ? 0.0 : 100.0 * double(count) / double(pixels);
    }
    std::optional<double> fullUmbraLitPercent() const {
        return fullUmbraRecorded ? std::optional<double>(percentOfPixels(fullUmbraLit)) : std::nullopt;
    }
};

// Throws std::runtime_error if a channel (options.channel, or the reference's hit) is
// missing or the sizes differ.
ErrorFigures compareImages(const ImageChannels& reference, const ImageChannels& test,
                           const CompareOptions& options = {});
// Reads only the channels needed from both files, then compareImages().
ErrorFigures compareFiles(const std::filesystem::path& reference, const std::filesystem::path& test,
                          const CompareOptions& options = {});

// Human-readable, several lines, and a JSON object with the same figures:
// {"channel","pixels","rms","rms_display" and "flip_mean" (if set),"mean_abs","max_abs","binary","misclassified",
//  "misclassified_percent","false_shadow","false_shadow_percent","false_light",
//  "false_light_percent","umbra_pixels","lit_pixels","umbra_lit","umbra_lit_percent",
//  "umbra_over","umbra_over_percent","lit_shadowed","lit_shadowed_percent","umbra_errors",
//  "umbra_errors_percent","full_umbra_pixels","full_umbra_lit","full_umbra_lit_percent"}.
// Every percentage is of `pixels`, the reference's hit pixels.
std::string formatText(const ErrorFigures& figures);
std::string formatJson(const ErrorFigures& figures);

// RGB bytes (row 0 at the top) for writePng(). With e = reference - test:
// red where e > 0 (test darker: false shadow, acne), blue where e < 0 (test brighter:
// false light, leaks), intensity sRGB-encoded min(|e| / heatMapFullScale, 1) so small
// errors stay visible; black where equal (and where e is NaN, which the figures report);
// mid grey (128) where the reference has hit = 0.
std::vector<uint8_t> errorHeatMap(const ImageChannels& reference, const ImageChannels& test,
                                  const CompareOptions& options = {});

}  // namespace shadowlab
