// A small PLY reader. It is written here because the only PLY library packaged in Debian
// is assimp, a large dependency for the two things we need: positions and polygons.
//
// Format (Greg Turk, "The PLY Polygon File Format", 1994): a text header declares the
// elements ("element vertex 8") and, for each, its properties in order ("property float
// x", "property list uchar int vertex_indices"); the body then holds every row of every
// element in header order, either as whitespace-separated text or as packed binary.
// Both body encodings are read through one "cursor" interface, so the row logic below
// exists once.
#include "scenes/ply_reader.h"

#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "scenes/error_text.h"
#include "scenes/float_range.h"
#include "scenes/read_file.h"
#include "scenes/scene_error.h"

namespace shadowlab {
namespace {

// The binary reader copies bytes straight into native numbers.
static_assert(std::endian::native == std::endian::little,
              "binary_little_endian PLY is decoded with memcpy");

enum class PlyType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyTypeInfo {
    std::string_view name, alias;   // PLY 1.0 names and their sized aliases
    size_t bytes;
    bool integral;
    double lo, hi;                  // range of the integral types
};

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::array<PlyTypeInfo, 8> kTypes{{
    {"char", "int8", 1, true, -128.0, 127.0},
    {"uchar", "uint8", 1, true, 0.0, 255.0},
    {"short", "int16", 2, true, -32768.0, 32767.0},
    {"ushort", "uint16", 2, true, 0.0, 65535.0},
    {"int", "int32", 4, true, -2147483648.0, 2147483647.0},
    {"uint", "uint32", 4, true, 0.0, 4294967295.0},
    {"float", "float32", 4, false, -kInf, kInf},
    {"double", "float64", 8, false, -kInf, kInf},
}};

const PlyTypeInfo& info(PlyType type) { return kTypes[size_t(type)]; }

std::optional<PlyType> typeNamed(std::string_view name) {
    for (size_t i = 0; i < kTypes.size(); ++i)
        if (kTypes[i].name == name || kTypes[i].alias == name) return PlyType(i);
    return std::nullopt;
}

struct PlyProperty {
    std::string name;
    PlyType type;                     // of the value, or of each list item
    std::optional<PlyType> countType; // set for list properties
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    bool binary = false;
    std::vector<PlyElement> elements;
    size_t bodyOffset = 0;   // first byte after "end_header\n"
    size_t bodyFirstLine = 0;
};

// ---- Header ---------------------------------------------------------------------------

class HeaderParser {
public:
    HeaderParser(const std::string& bytes, const std::string& file) : bytes_(bytes), file_(file) {}

    PlyHeader parse() {
        if (nextLine() != std::vector<std::string>{"ply"})
            fail("not a PLY file (the first line must be \"ply\")");
        bool sawFormat = false;
        for (;;) {
            const std::vector<std::string> words = nextLine();
            if (words.empty()) continue;
            const std::string& keyword = words[0];
            if (keyword == "end_header") break;
            if (keyword == "format") sawFormat = parseFormat(words);
            else if (keyword == "element") parseElement(words);
            else if (keyword == "property") parseProperty(words);
            else if (keyword != "comment" && keyword != "obj_info")
                fail("unknown header keyword " + inQuotes(keyword));
        }
        if (!sawFormat) fail("the header has no \"format\" line");
        // A row of an element without properties is no bytes at all: its count would make
        // the body loop run without reading (up to 2^64 times), so it is refused.
        for (const PlyElement& element : header_.elements) {
            if (element.properties.empty() && element.count > 0)
                fail("element " + inQuotes(element.name) + " has " + std::to_string(element.count) + " rows but no properties");
        }
        header_.bodyOffset = pos_;
        header_.bodyFirstLine = line_ + 1;
        return header_;
    }

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw SceneError(file_ + ": header line " + std::to_string(line_) + ": " + problem);
    }

    std::vector<std::string> nextLine() {
        if (pos_ >= bytes_.size()) fail("the file ends before \"end_header\"");
        size_t end = bytes_.find('\n', pos_);
        if (end == std::string::npos) end = bytes_.size();
        std::istringstream words(bytes_.substr(pos_, end - pos_));
        pos_ = end + 1;
        ++line_;
        std::vector<std::string> result;
        for (std::string word; words >> word;) result.push_back(word);
        return result;
    }

    bool parseFormat(const std::vector<std::string>& words) {
        if (words.size() != 3 || words[2] != "1.0") fail("expected \"format <encoding> 1.0\"");
        if (words[1] == "binary_big_endian") fail("binary_big_endian PLY is not supported");
        if (words[1] != "ascii" && words[1] != "binary_little_endian")
            fail("unknown format " + inQuotes(words[1]));
        header_.binary = words[1] == "binary_little_endian";
        return true;
    }

    void parseElement(const std::vector<std::string>& words) {
        PlyElement element;
        if (words.size() != 3) fail("expected \"element <name> <count>\"");
        element.name = words[1];
        const auto [end, error] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), element.count);
        if (error != std::errc() || end != words[2].data() + words[2].size())
            fail("element count " + inQuotes(words[2]) + " is not a non-negative integer");
        header_.elements.push_back(element);
    }

    void parseProperty(const std::vector<std::string>& words) {
        if (header_.elements.empty()) fail("\"property\" before any \"element\"");
        const bool isList = words.size() == 5 && words[1] == "list";
        if (!isList && words.size() != 3)
            fail("expected \"property <type> <name>\" or \"property list <count type> <type> <name>\"");
        PlyProperty property{words.back(), type(words[isList ? 3 : 1]), std::nullopt};
        if (isList) {
            property.countType = type(words[2]);
            if (!info(*property.countType).integral) fail("a list count must have an integer type");
        }
        header_.elements.back().properties.push_back(property);
    }

    PlyType type(const std::string& name) const {
        if (const auto found = typeNamed(name)) return *found;
        fail("unknown property type " + inQuotes(name));
    }

    const std::string& bytes_;
    const std::string& file_;
    size_t pos_ = 0, line_ = 0;
    PlyHeader header_;
};

// Where the data we keep sits in each row, checked once against the header.
struct PlyLayout {
    const PlyElement* vertex = nullptr;
    const PlyElement* face = nullptr;
    std::array<size_t, 3> xyz{};   // property indices in the vertex element
    std::optional<std::array<size_t, 3>> normal;   // nx, ny, nz, when the vertex element has all three
    size_t indexList = 0;          // property index in the face element
};

std::optional<size_t> propertyIndex(const PlyElement& element, std::string_view name) {
    for (size_t i = 0; i < element.properties.size(); ++i)
        if (element.properties[i].name == name) return i;
    return std::nullopt;
}

const PlyElement* elementNamed(const PlyHeader& header, std::string_view name) {
    for (const PlyElement& element : header.elements)
        if (element.name == name) return &element;
    return nullptr;
}

PlyLayout findLayout(const PlyHeader& header, const std::string& file) {
    auto fail = [&](const std::string& problem) { throw SceneError(file + ": " + problem); };
    PlyLayout layout;
    layout.vertex = elementNamed(header, "vertex");
    layout.face = elementNamed(header, "face");
    if (!layout.vertex) fail("no \"vertex\" element");
    if (!layout.face) fail("no \"face\" element (a point cloud has no surface to render)");
    for (size_t axis = 0; axis < 3; ++axis) {
        const char name[] = {char('x' + axis), '\0'};
        const auto index = propertyIndex(*layout.vertex, name);
        if (!index || layout.vertex->properties[*index].countType)
            fail(std::string("the vertex element has no scalar property \"") + name + "\"");
        layout.xyz[axis] = *index;
    }
    std::array<size_t, 3> normal{};
    size_t normalAxes = 0;
    for (size_t axis = 0; axis < 3; ++axis) {
        const std::string name = std::string("n") + char('x' + axis);
        const auto index = propertyIndex(*layout.vertex, name);
        if (index && layout.vertex->properties[*index].countType) fail("the vertex property " + inQuotes(name) + " is a list");
        if (index) normal[normalAxes++] = *index;
    }
    if (normalAxes == 3) layout.normal = normal;
    else if (normalAxes != 0) fail("the vertex element has some but not all of nx, ny, nz");
    auto list = propertyIndex(*layout.face, "vertex_indices");
    if (!list) list = propertyIndex(*layout.face, "vertex_index");
    if (!list || !layout.face->properties[*list].countType)
        fail("the face element has no list property \"vertex_indices\" or \"vertex_index\"");
    if (!info(layout.face->properties[*list].type).integral)
        fail("face vertex indices must have an integer type");
    layout.indexList = *list;
    return layout;
}

// ---- Body cursors: the next value of a given type, or nothing with a problem() --------

class AsciiCursor {
public:
    AsciiCursor(std::string_view text, size_t firstLine) : text_(text), line_(firstLine) {}

    std::optional<double> next(PlyType type) {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
            line_ += text_[pos_++] == '\n';
        if (pos_ == text_.size()) return failure("unexpected end of file (truncated?)");
        const size_t start = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
        const std::string_view token = text_.substr(start, pos_ - start);
        double value = 0.0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        const PlyTypeInfo& expected = info(type);
        const bool fits = !expected.integral ||
                          (value == std::trunc(value) && value >= expected.lo && value <= expected.hi);
        if (error != std::errc() || end != token.data() + token.size() || !fits)
            return failure("line " + std::to_string(line_) + ": " + inQuotes(token) +
                           " is not a valid " + std::string(expected.name));
        return value;
    }

    const std::string& problem() const { return problem_; }

private:
    std::optional<double> failure(std::string problem) {
        problem_ = std::move(problem);
        return std::nullopt;
    }

    std::string_view text_;
    size_t pos_ = 0, line_;
    std::string problem_;
};

template <class T>
double load(const char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return double(value);
}

class BinaryCursor {
public:
    explicit BinaryCursor(std::string_view data) : data_(data) {}

    std::optional<double> next(PlyType type) {
        const size_t size = info(type).bytes;
        if (data_.size() - pos_ < size) {
            problem_ = "truncated: the data ends after " + std::to_string(data_.size()) + " bytes";
            return std::nullopt;
        }
        const double value = decode(type, data_.data() + pos_);
        pos_ += size;
        return value;
    }

    const std::string& problem() const { return problem_; }

private:
    static double decode(PlyType type, const char* bytes) {
        switch (type) {
            case PlyType::Int8: return load<int8_t>(bytes);
            case PlyType::UInt8: return load<uint8_t>(bytes);
            case PlyType::Int16: return load<int16_t>(bytes);
            case PlyType::UInt16: return load<uint16_t>(bytes);
            case PlyType::Int32: return load<int32_t>(bytes);
            case PlyType::UInt32: return load<uint32_t>(bytes);
            case PlyType::Float32: return load<float>(bytes);
            case PlyType::Float64: return load<double>(bytes);
        }
        return 0.0;   // unreachable: every enumerator is handled above
    }

    std::string_view data_;
    size_t pos_ = 0;
    std::string problem_;
};

// ---- Rows -----------------------------------------------------------------------------

// Reads every row of every element in file order, keeping vertex positions and
// triangulated faces; errors name the element and the row (counted from 0).
template <class Cursor>
class BodyReader {
public:
    BodyReader(const PlyHeader& header, const PlyLayout& layout, Cursor cursor, const std::string& file)
        : header_(header), layout_(layout), cursor_(std::move(cursor)), file_(file) {}

    Mesh read() {
        mesh_.source = file_;
        for (const PlyElement& element : header_.elements) {
            element_ = &element;
            for (row_ = 0; row_ < element.count; ++row_) {
                readRow();
                if (&element == layout_.vertex) addVertex();
                if (&element == layout_.face) addFace();
            }
        }
        if (layout_.normal)
            for (const glm::uvec3& t : mesh_.triangles)
                for (int c = 0; c < 3; ++c) mesh_.cornerNormals.push_back(vertexNormals_[t[c]]);
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const {
        throw SceneError(file_ + ": element " + element_->name + " " + std::to_string(row_) + ": " + problem);
    }

    double value(PlyType type) {
        if (const std::optional<double> v = cursor_.next(type)) return *v;
        fail(cursor_.problem());
    }

    // Scalars land in scalars_[property]; the items of the face index list in indices_.
    void readRow() {
        scalars_.assign(element_->properties.size(), 0.0);
        indices_.clear();
        for (size_t p = 0; p < element_->properties.size(); ++p) {
            const PlyProperty& property = element_->properties[p];
            if (!property.countType) {
                scalars_[p] = value(property.type);
                continue;
            }
            const double count = value(*property.countType);
            if (count < 0) fail("negative list length " + std::to_string(int64_t(count)));
            const bool keep = element_ == layout_.face && p == layout_.indexList;
            for (uint64_t i = 0; i < uint64_t(count); ++i) {
                const double item = value(property.type);
                if (keep) indices_.push_back(item);
            }
        }
    }

    void addVertex() {
        const glm::dvec3 p(scalars_[layout_.xyz[0]], scalars_[layout_.xyz[1]], scalars_[layout_.xyz[2]]);
        if (!roundsToFiniteFloat(p.x) || !roundsToFiniteFloat(p.y) || !roundsToFiniteFloat(p.z)) {
            std::ostringstream text;
            text << "position (" << p.x << ", " << p.y << ", " << p.z << ") is not finite as a float";
            fail(text.str());
        }
        mesh_.positions.emplace_back(p);
        if (!layout_.normal) return;
        const auto& axes = *layout_.normal;
        const glm::dvec3 n(scalars_[axes[0]], scalars_[axes[1]], scalars_[axes[2]]);
        if (!roundsToFiniteFloat(n.x) || !roundsToFiniteFloat(n.y) || !roundsToFiniteFloat(n.z)) {
            std::ostringstream text;
            text << "normal (" << n.x << ", " << n.y << ", " << n.z << ") is not finite as a float";
            fail(text.str());
        }
        vertexNormals_.emplace_back(n);
    }

    void addFace() {
        if (indices_.size() < 3)
            fail("a face needs at least 3 vertices, this one has " + std::to_string(indices_.size()));
        const double vertexCount = double(layout_.vertex->count);
        for (double index : indices_) {
            if (index < 0 || index >= vertexCount)
                fail("vertex index " + std::to_string(int64_t(index)) + " is out of range (the file has " +
                     std::to_string(layout_.vertex->count) + " vertices)");
        }
        for (size_t i = 1; i + 1 < indices_.size(); ++i)
            mesh_.triangles.emplace_back(uint32_t(indices_[0]), uint32_t(indices_[i]), uint32_t(indices_[i + 1]));
    }

    const PlyHeader& header_;
    const PlyLayout& layout_;
    Cursor cursor_;
    const std::string& file_;
    const PlyElement* element_ = nullptr;
    uint64_t row_ = 0;
    std::vector<double> scalars_, indices_;
    std::vector<glm::vec3> vertexNormals_;   // nx, ny, nz per vertex, when the file has them
    Mesh mesh_;
};

}  // namespace

Mesh parsePly(const std::string& bytes, const std::string& path) {
    const PlyHeader header = HeaderParser(bytes, path).parse();
    const PlyLayout layout = findLayout(header, path);
    const std::string_view body = std::string_view(bytes).substr(std::min(header.bodyOffset, bytes.size()));
    if (header.binary) return BodyReader(header, layout, BinaryCursor(body), path).read();
    return BodyReader(header, layout, AsciiCursor(body, header.bodyFirstLine), path).read();
}

Mesh readPly(const std::string& path) { return parsePly(readWholeFile(path), path); }

}  // namespace shadowlab
