// Error figures and heat map. Sums run sequentially in pixel order, in double, so the
// figures are the same bytes on every run and thread count.
#include "shading/compare.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "scenes/error_text.h"
#include "shading/tonemap.h"

namespace shadowlab {
namespace {

struct ComparedChannels {
    const std::vector<float>& reference;
    const std::vector<float>& test;
    const std::vector<float>& hit;  // of the reference
};

std::string describe(const ImageChannels& image) {
    return image.source.empty() ? std::string("(in memory)") : "'" + oneLine(image.source) + "'";
}

ComparedChannels channelsToCompare(const ImageChannels& reference, const ImageChannels& test,
                                   const CompareOptions& options) {
    if (reference.width != test.width || reference.height != test.height) {
        throw std::runtime_error("cannot compare " + describe(reference) + " (" +
                                 std::to_string(reference.width) + " x " + std::to_string(reference.height) +
                                 ") with " + describe(test) + " (" + std::to_string(test.width) + " x " +
                                 std::to_string(test.height) + "): sizes differ");
    }
    return {reference.at(options.channel), test.at(options.channel), reference.at(channel::hit)};
}

bool isBinary(float v) { return v == 0.0f || v == 1.0f; }

std::string formatLine(const char* label, double value) {
    char line[96];
    std::snprintf(line, sizeof line, "  %-16s %.6g\n", label, value);
    return line;
}

std::string formatCount(const char* label, uint64_t count, double percent, const char* meaning) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-16s %llu (%.4f%%)%s\n", label, (unsigned long long)count, percent,
                  meaning);
    return line;
}

// Umbra errors need a margin on both sides: a reference estimated from n samples puts a
// point in the umbra only when (almost) no sample sees the light, and a filtered technique
// may be off by a little everywhere; only gross errors, light in the umbra or shadow in
// full light, are counted.
void countUmbraErrors(float ref, float tst, const CompareOptions& options, ErrorFigures& f) {
    if (ref < options.umbraThreshold) {
        ++f.umbraPixels;
        f.umbraLit += tst > options.umbraTolerance;
    }
    f.umbraOver += tst < options.umbraThreshold && ref > options.umbraTolerance;
    if (ref > 1.0f - options.umbraThreshold) {
        ++f.litPixels;
        f.litShadowed += tst < 1.0f - options.umbraTolerance;
    }
    // The finer figure: where the reference is dark to its last ray, any light the test lets
    // through above a fiftieth is wrong, and the 0.1 tolerance would hide most of it.
    if (ref < options.fullUmbraThreshold) {
        ++f.fullUmbraPixels;
        f.fullUmbraLit += tst > options.fullUmbraTolerance;
    }
}

}  // namespace

ErrorFigures compareImages(const ImageChannels& reference, const ImageChannels& test,
                           const CompareOptions& options) {
    const ComparedChannels c = channelsToCompare(reference, test, options);
    ErrorFigures f;
    f.channel = options.channel;
    double sumSquares = 0.0, sumAbs = 0.0;
    for (size_t k = 0; k < c.hit.size(); ++k) {
        if (c.hit[k] != 1.0f) {
            continue;
        }
        const float ref = c.reference[k], tst = c.test[k];
        const double e = double(ref) - double(tst);
        ++f.pixels;
        sumSquares += e * e;
        sumAbs += std::abs(e);
        if (std::isnan(e) || std::abs(e) > f.maxAbs) {  // NaN stays: nothing compares above it
            f.maxAbs = std::abs(e);
        }
        f.binary = f.binary && isBinary(ref) && isBinary(tst);
        const bool refLit = ref >= options.litThreshold, testLit = tst >= options.litThreshold;
        f.falseShadow += refLit && !testLit;
        f.falseLight += !refLit && testLit;
        countUmbraErrors(ref, tst, options, f);
    }
    if (f.pixels > 0) {
        f.rms = std::sqrt(sumSquares / double(f.pixels));
        f.meanAbs = sumAbs / double(f.pixels);
    }
    return f;
}

ErrorFigures compareFiles(const std::filesystem::path& reference, const std::filesystem::path& test,
                          const CompareOptions& options) {
    return compareImages(readExr(reference, {options.channel, channel::hit}),
                         readExr(test, {options.channel}), options);
}

std::string formatText(const ErrorFigures& f) {
    std::string text = "channel " + f.channel + ": " + std::to_string(f.pixels) +
                       " pixels with hit = 1 in the reference" + (f.binary ? " (binary values)" : "") + "\n";
    text += formatLine("RMS error", f.rms);
    if (f.rmsDisplay) text += formatLine("RMS, display", *f.rmsDisplay);
    if (f.flipMean) text += formatLine("FLIP mean", *f.flipMean);
    text += formatLine("mean |error|", f.meanAbs);
    text += formatLine("max |error|", f.maxAbs);
    text += formatCount("misclassified", f.misclassified(), f.percentOfPixels(f.misclassified()), "");
    text += formatCount("false shadow", f.falseShadow, f.percentOfPixels(f.falseShadow),
                        "  lit in the reference, shadowed here (acne)");
    text += formatCount("false light", f.falseLight, f.percentOfPixels(f.falseLight),
                        "  shadowed in the reference, lit here (leaks)");
    text += formatCount("umbra lit", f.umbraLit, f.percentOfPixels(f.umbraLit),
                        ("  of " + std::to_string(f.umbraPixels) + " umbra pixels in the reference, lit here").c_str());
    if (f.fullUmbraRecorded)
        text += formatCount("umbra lit 0.02", f.fullUmbraLit, f.percentOfPixels(f.fullUmbraLit),
                            ("  of " + std::to_string(f.fullUmbraPixels) +
                             " full umbra pixels (V < 0.001), above 0.02 here").c_str());
    else
        text += "  umbra lit 0.02   not recorded\n";
    text += formatCount("umbra over", f.umbraOver, f.percentOfPixels(f.umbraOver),
                        "  umbra here where the reference sees the light (V > 0.1 there)");
    text += formatCount("lit shadowed", f.litShadowed, f.percentOfPixels(f.litShadowed),
                        ("  of " + std::to_string(f.litPixels) + " fully lit pixels in the reference, shadowed here").c_str());
    return text;
}

std::string formatJson(const ErrorFigures& f) {
    nlohmann::ordered_json j;
    j["channel"] = f.channel;
    j["pixels"] = f.pixels;
    j["rms"] = f.rms;
    if (f.rmsDisplay) j["rms_display"] = *f.rmsDisplay;
    if (f.flipMean) j["flip_mean"] = *f.flipMean;
    j["mean_abs"] = f.meanAbs;
    j["max_abs"] = f.maxAbs;
    j["binary"] = f.binary;
    j["misclassified"] = f.misclassified();
    j["misclassified_percent"] = f.percentOfPixels(f.misclassified());
    j["false_shadow"] = f.falseShadow;
    j["false_shadow_percent"] = f.percentOfPixels(f.falseShadow);
    j["false_light"] = f.falseLight;
    j["false_light_percent"] = f.percentOfPixels(f.falseLight);
    j["umbra_pixels"] = f.umbraPixels;
    j["lit_pixels"] = f.litPixels;
    j["umbra_lit"] = f.umbraLit;
    j["umbra_lit_percent"] = f.percentOfPixels(f.umbraLit);
    j["umbra_over"] = f.umbraOver;
    j["umbra_over_percent"] = f.percentOfPixels(f.umbraOver);
    j["lit_shadowed"] = f.litShadowed;
    j["lit_shadowed_percent"] = f.percentOfPixels(f.litShadowed);
    j["umbra_errors"] = f.umbraErrors();
    j["umbra_errors_percent"] = f.percentOfPixels(f.umbraErrors());
    if (f.fullUmbraRecorded) {
        j["full_umbra_pixels"] = f.fullUmbraPixels;
        j["full_umbra_lit"] = f.fullUmbraLit;
        j["full_umbra_lit_percent"] = f.percentOfPixels(f.fullUmbraLit);
    }
    return j.dump(2);
}

std::vector<uint8_t> errorHeatMap(const ImageChannels& reference, const ImageChannels& test,
                                  const CompareOptions& options) {
    const ComparedChannels c = channelsToCompare(reference, test, options);
    std::vector<uint8_t> rgb(c.hit.size() * 3, 0);
    for (size_t k = 0; k < c.hit.size(); ++k) {
        uint8_t* pixel = &rgb[3 * k];
        if (c.hit[k] != 1.0f) {
            pixel[0] = pixel[1] = pixel[2] = 128;
            continue;
        }
        const float e = c.reference[k] - c.test[k];
        const uint8_t intensity = toSrgb8(std::abs(e) / options.heatMapFullScale);
        pixel[0] = e > 0.0f ? intensity : 0;  // red: test darker than the reference
        pixel[2] = e < 0.0f ? intensity : 0;  // blue: test brighter than the reference
    }
    return rgb;
}

}  // namespace shadowlab
