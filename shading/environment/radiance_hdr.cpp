#include "shading/environment/radiance_hdr.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// The bytes with a read position; every read checks what is left.
class Reader {
public:
    Reader(const std::string& bytes, const std::string& name) : bytes_(bytes), name_(name) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error("Radiance HDR " + name_ + ": " + what + " (at byte " + std::to_string(at_) + ")");
    }
    bool atEnd() const { return at_ >= bytes_.size(); }
    size_t left() const { return bytes_.size() - at_; }
    uint8_t byte() {
        if (atEnd()) fail("truncated");
        return uint8_t(bytes_[at_++]);
    }
    // One header line without its '\n'; lines are short, so a long one is not a header.
    std::string line() {
        std::string text;
        for (uint8_t c = byte(); c != '\n'; c = byte()) {
            if (text.size() > 4096) fail("a header line longer than 4096 bytes");
            text.push_back(char(c));
        }
        return text;
    }

private:
    const std::string& bytes_;
    const std::string& name_;
    size_t at_ = 0;
};

// The header's exposure product; the FORMAT, if given, must be RGBE.
double readHeader(Reader& in) {
    const std::string magic = in.line();
    if (magic.rfind("#?", 0) != 0) in.fail("no '#?' signature");
    double exposure = 1.0;
    for (std::string text = in.line(); !text.empty(); text = in.line()) {
        if (text.rfind("FORMAT=", 0) == 0 && text != "FORMAT=32-bit_rle_rgbe") in.fail("unsupported " + text);
        if (text.rfind("EXPOSURE=", 0) == 0) {
            size_t used = 0;
            double e = 0.0;
            try {
                e = std::stod(text.substr(9), &used);
            } catch (const std::exception&) {
                in.fail("unreadable " + text);
            }
            if (!(e > 0.0) || !std::isfinite(e)) in.fail("EXPOSURE must be a positive number, not " + text.substr(9));
            exposure *= e;
        }
    }
    if (!(exposure > 0.0) || !std::isfinite(exposure)) in.fail("the EXPOSURE product is not a positive number");
    return exposure;
}

// "-Y H +X W", each within 1..maxSide.
glm::ivec2 readResolution(Reader& in, int maxSide) {
    const std::string text = in.line();
    int height = 0, width = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "-Y %d +X %d%c", &height, &width, &tail) != 2) {
        in.fail("resolution line '" + text.substr(0, 40) + "' is not '-Y H +X W' (other orientations are not lat-long maps)");
    }
    if (width < 1 || height < 1 || width > maxSide || height > maxSide) {
        in.fail(std::to_string(width) + " x " + std::to_string(height) + " pixels; 1 to " + std::to_string(maxSide) + " a side");
    }
    return {width, height};
}

// One scanline's RGBE bytes into rgbe (4 per pixel, interleaved).
void readScanline(Reader& in, int width, std::vector<uint8_t>& rgbe) {
    uint8_t first[4];
    for (uint8_t& b : first) b = in.byte();
    const bool rle = width >= 8 && width < 32768 && first[0] == 2 && first[1] == 2 && ((first[2] << 8) | first[3]) == width;
    if (!rle) {
        std::copy(first, first + 4, rgbe.begin());
        for (size_t k = 4; k < size_t(width) * 4; ++k) rgbe[k] = in.byte();
        return;
    }
    for (int channel = 0; channel < 4; ++channel) {
        for (int x = 0; x < width;) {
            const int count = in.byte();
            const bool run = count > 128;
            const int length = run ? count - 128 : count;
            if (length == 0 || x + length > width) in.fail("a run-length scanline overruns its " + std::to_string(width) + " pixels");
            const uint8_t repeated = run ? in.byte() : 0;
            for (int k = 0; k < length; ++k, ++x) rgbe[size_t(x) * 4 + size_t(channel)] = run ? repeated : in.byte();
        }
    }
}

glm::vec3 radianceOf(const uint8_t* rgbe, double exposure) {
    if (rgbe[3] == 0) return glm::vec3(0.0f);
    const double scale = portable::detail::powerOfTwo(int(rgbe[3]) - 136) / exposure;
    return glm::vec3((rgbe[0] + 0.5) * scale, (rgbe[1] + 0.5) * scale, (rgbe[2] + 0.5) * scale);
}

}  // namespace

EnvironmentMap parseRadianceHdr(const std::string& bytes, const std::string& name, int maxSide) {
    Reader in(bytes, name);
    const double exposure = readHeader(in);
    const glm::ivec2 size = readResolution(in, maxSide);
    // The fewest bytes a scanline can take (run-length: a 4-byte header and, per channel,
    // runs of at most 127 in 2 bytes each): a file too short for its rows is refused before
    // its image is allocated.
    const size_t fewest = size.x >= 8 ? 4 + 4 * 2 * ((size_t(size.x) + 126) / 127) : 4 * size_t(size.x);
    if (in.left() / fewest < size_t(size.y)) in.fail("truncated: too few bytes for " + std::to_string(size.y) + " scanlines");
    EnvironmentMap map;
    map.width = size.x, map.height = size.y;
    map.radiance.resize(size_t(size.x) * size_t(size.y));
    std::vector<uint8_t> rgbe(size_t(size.x) * 4);
    for (int j = 0; j < size.y; ++j) {
        readScanline(in, size.x, rgbe);
        for (int i = 0; i < size.x; ++i) map.radiance[size_t(j) * size_t(size.x) + size_t(i)] = radianceOf(&rgbe[size_t(i) * 4], exposure);
    }
    return map;
}

}  // namespace shadowlab
