// Scoring a technique against the exact reference (conventions.md, "Figures and errors"):
// the work `shadowlab render --error-map` and `shadowlab sweep` share. The reference is
// the same camera view rendered by the technique's Technique::referenceName (`reference`
// for hard shadows, `reference-soft` for soft ones); a frame is scored by compareImages()
// over the reference's hit pixels, on V for a visibility technique and on the luminance Y
// of its radiance for a radiance technique (scoredChannel()).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "frame/render.h"
#include "shading/compare.h"
#include "shading/image_io.h"

namespace shadowlab {

// The channel a technique's frames are scored on: V, or Y for radiance.
const char* scoredChannel(TechniqueOutput output);

// A light's V channel (conventions.md, "Buffers written to disk"): "V" in a frame of one
// light, "lightK.V" for scene.lights[K] in a frame of several (an EXR layer per light).
std::string visibilityChannel(size_t light, size_t lightCount);
// The V channels an image holds, in the order of the lights: {"V"}, or "light0.V",
// "light1.V", ... as far as they run without a gap; none if it has neither.
std::vector<std::string> visibilityChannels(const ImageChannels& image);

// The channels a frame is scored on: hit (from its G-buffer) and scoredChannel(): V (each
// light's visibilityChannel() in a frame of several lights), or Y,
// the Rec. 709 luminance of the frame's radiance, with kDisplayLuminance beside it, Y of the
// radiance tone mapped for display (shading/tonemap.h, Reinhard at exposure 0).
inline constexpr const char* kDisplayLuminance = "Y.display";
ImageChannels scoredImage(const Frame& frame);

// Renders the scene with the technique named referenceName (at its default settings); the
// technique reports on `progress` if one is given. renderReferenceImage() returns the
// frame's scoredImage(), renderReferenceFrame() the frame itself (its shaded image too).
Frame renderReferenceFrame(const PreparedScene& prepared, raster::SimdLevel simd,
                           const std::string& referenceName = "reference", Progress* progress = nullptr);
ImageChannels renderReferenceImage(const PreparedScene& prepared, raster::SimdLevel simd,
                                   const std::string& referenceName = "reference", Progress* progress = nullptr);

// The scored channel of `test` (the scoredImage() of a frame whose technique gives `output`)
// against the reference's (compareImages with the default options otherwise); for radiance,
// also the RMS of the display luminance (ErrorFigures::rmsDisplay). With several lights the
// figures are over every (pixel, light) pair: the lights' V images stacked into one, so
// each light's hit pixels count once per light, and a figure with one light is that
// light's (docs/many-lights.md; scoreLights() gives each light's own). Throws
// std::invalid_argument if the reference lacks that channel (a radiance technique scored
// against a visibility reference, or the other way round).
ErrorFigures scoreImage(const ImageChannels& reference, const ImageChannels& test, TechniqueOutput output);
// Each light's figures, V against V, in the order of visibilityChannels(reference); one
// entry (scoreImage's) for a frame of one light. Throws std::invalid_argument as
// scoreImage does, or if `test` lacks one of the reference's lights.
std::vector<ErrorFigures> scoreLights(const ImageChannels& reference, const ImageChannels& test);
// scoreImage() of the frame's scoredImage(), for a caller that needs no more of it.
ErrorFigures scoreFrame(const ImageChannels& reference, const Frame& frame);

// FLIP (shading/flip.h, Andersson et al. 2020) of a technique's shaded image against the
// reference's (both linear radiance, width x height), each tone mapped for display as
// kDisplayLuminance is (Reinhard at exposure 0), at kFlipPixelsPerDegree: the mean of the
// error map over the pixels where `hit` (the reference's) is 1, as every figure here; 0 if
// there are none. The same bits for any thread count. Throws std::invalid_argument if a size
// differs.
double flipFigure(const std::vector<glm::vec3>& referenceShaded, const std::vector<glm::vec3>& testShaded, int width,
                  int height, const std::vector<float>& hit);
// Linear radiance as it is displayed: toneMap() with the default options (Reinhard at
// exposure 0), each channel in [0, 1]. FLIP's input, and kDisplayLuminance's.
std::vector<glm::vec3> displayedImage(const std::vector<glm::vec3>& radiance);
// A reference's figures and its shaded image (Frame::radiance) beside them: what a technique's
// frame is scored against, FLIP included.
struct ScoredReference {
    ImageChannels scored;                // scoredImage()
    std::vector<glm::vec3> shaded;       // linear radiance
};
ScoredReference scoredReference(const Frame& frame);
// scoreImage() of the frame's scoredImage() (passed in, `scored`, to be kept by the caller),
// with flipMean set from the shaded images.
ErrorFigures scoreFrame(const ScoredReference& reference, const ImageChannels& scored, const Frame& frame);

// Error-map colours, 8-bit sRGB. Red and blue as in `shadowlab compare`'s heat map, at
// full saturation so that they stand out from the grey underneath.
inline constexpr std::array<uint8_t, 3> kFalseShadowColour{255, 0, 0};    // acne
inline constexpr std::array<uint8_t, 3> kFalseLightColour{0, 160, 255};   // leaks, peter-panning

// RGB bytes (row 0 at the top) for writePng(): the tone-mapped luminance of `shaded`
// (the technique's image, linear radiance) encoded as sRGB and halved, so that the
// scene stays readable behind the marks; over it, pixels the technique misclassifies
// (CompareOptions::litThreshold, over the reference's hit pixels) in kFalseShadowColour
// or kFalseLightColour; with several lights' V (visibilityChannels()), a pixel any light
// misclassifies, false light drawn over false shadow.
std::vector<uint8_t> errorMapImage(const ImageChannels& reference, const ImageChannels& test,
                                   const std::vector<glm::vec3>& shaded, const std::string& scored = channel::V);

}  // namespace shadowlab
