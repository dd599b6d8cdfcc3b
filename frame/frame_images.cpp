#include "frame/frame_images.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "frame/registry.h"
#include "frame/score.h"
#include "scenes/scene_limits.h"
#include "shading/tonemap.h"
#include "shadows/debug_buffers.h"
#include "shadows/technique.h"

namespace shadowlab {
namespace {

// Each path field once, for the functions that treat them all alike.
template <class Images, class Visit>
void forEachPath(Images& images, Visit visit) {
    for (auto* path : {&images.image, &images.errorMap, &images.visibility, &images.referenceImage,
                       &images.referenceVisibility})
        visit(*path);
    for (auto& path : images.debugBuffers) visit(path);
}

// debugPictures() of one folder, without its subfolders.
std::vector<std::string> picturesIn(const std::filesystem::path& base, const std::filesystem::path& directory,
                                    const std::string& technique) {
    std::vector<std::string> pictures;
    if (!std::filesystem::is_directory(directory)) return pictures;
    const auto ownedByLongerName = [&](const std::string& file) {
        return std::ranges::any_of(techniques(), [&](const Technique& other) {
            return other.name.starts_with(technique + "-") && file.starts_with(other.name + "-");
        });
    };
    for (const auto& entry : std::filesystem::directory_iterator(directory)) {
        const std::string extension = entry.path().extension().string(), file = entry.path().filename().string();
        if (entry.is_regular_file() && (extension == ".png" || extension == ".svg") &&
            file.starts_with(technique + "-") && !ownedByLongerName(file))
            pictures.push_back(relativePath(entry.path(), base));
    }
    std::ranges::sort(pictures);
    return pictures;
}

}  // namespace

bool FrameImages::empty() const {
    bool none = true;
    forEachPath(*this, [&](const std::string& path) { none = none && path.empty(); });
    return none;
}

std::string relativePath(const std::filesystem::path& path, const std::filesystem::path& base) {
    // absolute() refuses an empty path: that of a file in the working directory has no parent.
    const auto normal = [](const std::filesystem::path& p) {
        return std::filesystem::absolute(p.empty() ? "." : p).lexically_normal();
    };
    return normal(path).lexically_relative(normal(base)).generic_string();
}

std::vector<float> meanVisibility(const Frame& frame) {
    if (frame.passes.size() <= 1) return frame.shadow.visibility;
    std::vector<float> mean(frame.gbuffer.pixelCount(), 0.0f);
    for (const LightPass& pass : frame.passes) {
        for (size_t k = 0; k < mean.size(); ++k) mean[k] += pass.shadow.visibility[k];
    }
    for (float& v : mean) v /= float(frame.passes.size());
    return mean;
}

FrameImages writeFramePictures(const std::filesystem::path& base, const std::filesystem::path& folder,
                               const std::string& name, const Frame& frame, const ImageChannels* reference,
                               const ToneMapOptions& tone) {
    if (!folder.empty()) std::filesystem::create_directories(folder);
    const int width = frame.gbuffer.width, height = frame.gbuffer.height;
    const auto write = [&](const std::string& suffix, const std::vector<uint8_t>& rgb) {
        const std::filesystem::path path = folder / (name + "-" + suffix + ".png");
        writePng(path, width, height, rgb);
        return relativePath(path, base);
    };
    FrameImages images;
    images.image = write("image", toSrgb8Image(frame.radiance, tone));
    if (reference)
        images.errorMap = write("error-map", errorMapImage(*reference, scoredImage(frame), frame.radiance,
                                                          scoredChannel(frame.output)));
    if (frame.output == TechniqueOutput::Visibility)
        images.visibility = write("visibility", greyImage(meanVisibility(frame), 0.0f, 1.0f));
    return images;
}

std::vector<std::string> debugPictures(const std::filesystem::path& base, const std::filesystem::path& directory,
                                       const std::string& technique) {
    std::vector<std::string> pictures = picturesIn(base, directory, technique);
    for (size_t light = 0; std::filesystem::is_directory(directory / lightDebugFolder(light)); ++light) {
        const std::vector<std::string> own = picturesIn(base, directory / lightDebugFolder(light), technique);
        pictures.insert(pictures.end(), own.begin(), own.end());
    }
    return pictures;
}

std::optional<size_t> debugPictureLight(const std::string& path) {
    const std::string folder = std::filesystem::path(path).parent_path().filename().string();
    for (size_t light = 0; light < kMaxSceneLights; ++light)
        if (folder == lightDebugFolder(light)) return light;
    return std::nullopt;
}

FrameImages withPaths(const FrameImages& images, const std::function<std::string(const std::string&)>& change) {
    FrameImages changed = images;
    forEachPath(changed, [&](std::string& path) {
        if (!path.empty()) path = change(path);
    });
    return changed;
}

FrameImages rebased(const FrameImages& images, const std::filesystem::path& from, const std::filesystem::path& to) {
    return withPaths(images, [&](const std::string& path) { return relativePath(from / path, to); });
}

std::string formatFrameImagesJson(const FrameImages& images) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    const auto add = [&](const char* key, const std::string& path) {
        if (!path.empty()) j[key] = path;
    };
    add("image", images.image);
    add("error_map", images.errorMap);
    add("visibility", images.visibility);
    add("reference_image", images.referenceImage);
    add("reference_visibility", images.referenceVisibility);
    if (!images.debugBuffers.empty()) j["debug_buffers"] = images.debugBuffers;
    return j.dump();
}

}  // namespace shadowlab
