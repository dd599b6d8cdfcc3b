// Writes the EXR fuzz target's seeds (tests/fuzz/corpus/exr_reader): tiny images covering
// the layouts OpenEXR reads, so the fuzzer starts from every path rather than one.
//   make_exr_seeds <directory>
#include <cstdio>
#include <string>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfTiledOutputFile.h>
#include <half.h>

namespace {

// One channel of `type` per name over the window (min, max), filled with a ramp.
struct Channels {
    std::vector<std::vector<float>> floats;
    std::vector<std::vector<half>> halves;
    std::vector<std::vector<unsigned>> uints;
};

Imf::FrameBuffer fill(Imf::Header& header, Channels& storage, const std::vector<std::string>& names, Imf::PixelType type) {
    const Imath::Box2i window = header.dataWindow();
    const size_t width = size_t(window.max.x - window.min.x + 1), count = width * size_t(window.max.y - window.min.y + 1);
    Imf::FrameBuffer buffer;
    for (size_t k = 0; k < names.size(); ++k) {
        header.channels().insert(names[k], Imf::Channel(type));
        char* base = nullptr;
        size_t bytes = 0;
        if (type == Imf::FLOAT) {
            storage.floats.emplace_back(count);
            for (size_t i = 0; i < count; ++i) storage.floats.back()[i] = float(i + k) / 7.0f - 1.0f;
            base = reinterpret_cast<char*>(storage.floats.back().data()), bytes = sizeof(float);
        } else if (type == Imf::HALF) {
            storage.halves.emplace_back(count);
            for (size_t i = 0; i < count; ++i) storage.halves.back()[i] = half(float(i * 3 + k) / 5.0f);
            base = reinterpret_cast<char*>(storage.halves.back().data()), bytes = sizeof(half);
        } else {
            storage.uints.emplace_back(count);
            for (size_t i = 0; i < count; ++i) storage.uints.back()[i] = unsigned(i * 977 + k);
            base = reinterpret_cast<char*>(storage.uints.back().data()), bytes = sizeof(unsigned);
        }
        // The slice's origin is pixel (0, 0), so shift the base by the window's corner.
        base -= (ptrdiff_t(window.min.y) * ptrdiff_t(width) + window.min.x) * ptrdiff_t(bytes);
        buffer.insert(names[k], Imf::Slice(type, base, bytes, bytes * width));
    }
    return buffer;
}

void writeScanlines(const std::string& path, Imf::Header header, const std::vector<std::string>& names, Imf::PixelType type) {
    Channels storage;
    const Imf::FrameBuffer buffer = fill(header, storage, names, type);
    Imf::OutputFile file(path.c_str(), header);
    file.setFrameBuffer(buffer);
    file.writePixels(header.dataWindow().max.y - header.dataWindow().min.y + 1);
}

void writeTiles(const std::string& path, Imf::Header header, const std::vector<std::string>& names, Imf::PixelType type) {
    header.setTileDescription(Imf::TileDescription(4, 4, Imf::ONE_LEVEL));
    Channels storage;
    const Imf::FrameBuffer buffer = fill(header, storage, names, type);
    Imf::TiledOutputFile file(path.c_str(), header);
    file.setFrameBuffer(buffer);
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
}

Imf::Header header(Imath::Box2i window, Imf::Compression compression, Imf::LineOrder order = Imf::INCREASING_Y) {
    Imf::Header h(window, window);
    h.compression() = compression;
    h.lineOrder() = order;
    return h;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_exr_seeds <directory>\n");
        return 2;
    }
    const std::string dir = argv[1];
    using Box = Imath::Box2i;
    using V = Imath::V2i;
    // What `render` writes: FLOAT channels, ZIP, window at the origin.
    writeScanlines(dir + "/float-rgb-zip.exr", header(Box(V(0, 0), V(3, 2)), Imf::ZIP_COMPRESSION), {"R", "G", "B"}, Imf::FLOAT);
    // A window away from the origin, HALF, RLE, rows stored bottom-up.
    writeScanlines(dir + "/half-window-rle.exr", header(Box(V(-2, 3), V(2, 4)), Imf::RLE_COMPRESSION, Imf::DECREASING_Y),
                   {"A", "Y"}, Imf::HALF);
    // UINT channels, no compression; names of our G-buffer (docs/conventions.md).
    writeScanlines(dir + "/uint-none.exr", header(Box(V(0, 0), V(2, 2)), Imf::NO_COMPRESSION), {"hit", "depth"}, Imf::UINT);
    // Tiled, PIZ (wavelet + Huffman) and B44 (lossy, 4x4 blocks).
    writeTiles(dir + "/tiled-half-piz.exr", header(Box(V(0, 0), V(7, 5)), Imf::PIZ_COMPRESSION), {"B", "G", "R"}, Imf::HALF);
    writeScanlines(dir + "/half-b44.exr", header(Box(V(0, 0), V(7, 3)), Imf::B44_COMPRESSION), {"V"}, Imf::HALF);
    // PXR24 (lossy float) and DWAB (the compression of the HDR environment maps).
    writeScanlines(dir + "/float-pxr24.exr", header(Box(V(0, 0), V(4, 3)), Imf::PXR24_COMPRESSION), {"Z"}, Imf::FLOAT);
    writeScanlines(dir + "/half-dwab.exr", header(Box(V(0, 0), V(7, 7)), Imf::DWAB_COMPRESSION), {"R", "G", "B"}, Imf::HALF);
    return 0;
}
