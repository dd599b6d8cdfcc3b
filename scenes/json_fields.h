// Checked reading of JSON values for the scene loader. Every value carries its file and
// field path ("lights[0].radius"), and every read checks type, finiteness and range, so
// that a mistake in a scene file is reported where it is instead of surfacing later as
// a black image or a NaN in a shadow map.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "scenes/scene_error.h"

namespace shadowlab {

// An allowed range for a number; it both checks the value and words the error message.
struct Interval {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool loOpen = true, hiOpen = true;

    bool contains(double x) const;
    std::string describe() const;   // "> 0", "in (0, 90]"
};

// A number as error messages show it: the shortest of printf's %g.
std::string formatNumber(double x);

inline constexpr Interval kAnyNumber{};
inline constexpr Interval kPositive{0.0, std::numeric_limits<double>::infinity(), true, true};
inline constexpr Interval kNonNegative{0.0, std::numeric_limits<double>::infinity(), false, true};
inline constexpr Interval kUnitInterval{0.0, 1.0, false, false};

class JsonObject;

// Parses a whole document; syntax errors and numbers beyond double range (nlohmann
// rejects "1e999") become SceneErrors naming the file, the field being read and the
// line and column.
nlohmann::json parseJson(const std::string& text, const std::string& file);

// One JSON value of a scene file, with the file name and the path that leads to it.
class JsonField {
public:
    JsonField(const nlohmann::json& value, std::string file, std::string path);

    [[noreturn]] void fail(const std::string& problem) const;
    // A file's error met reading this field (a mesh, a texture), located at it; a
    // MissingFileError stays one.
    [[noreturn]] void fail(const SceneError& cause) const;
    const nlohmann::json& raw() const { return *value_; }

    float number(Interval range = kAnyNumber) const;   // finite, representable as float
    int integer(Interval range) const;
    bool boolean() const;
    std::string string() const;
    glm::vec3 vec3(Interval range = kAnyNumber) const;   // [x, y, z]
    std::vector<JsonField> elements() const;              // any array
    std::vector<JsonField> elements(size_t count) const;  // an array of exactly count
    JsonObject object() const;
    JsonObject object(const std::vector<std::string_view>& allowedKeys) const;

    // One of a fixed set of names, e.g. {"point", LightType::Point}.
    template <class Enum, size_t N>
    Enum choice(const std::array<std::pair<std::string_view, Enum>, N>& names) const;

private:
    JsonField child(std::string path, const nlohmann::json& value) const;
    [[noreturn]] void failType(const char* expected) const;
    [[noreturn]] void failChoice(const std::vector<std::string_view>& allowed) const;

    const nlohmann::json* value_;
    std::string file_, path_;
    friend class JsonObject;

// Parses a whole document; syntax errors and numbers beyond double range (nlohmann
// rejects "1e999") become SceneErrors naming the file, the field being read and the
// line and column.
nlohmann::json parseJson(const std::string& text, const std::string& file);
};

// A JSON object; keys are looked up by name and unknown keys can be rejected, which
// catches typos such as "radus" that would otherwise silently fall back to a default.
class JsonObject {
public:
    explicit JsonObject(JsonField field);

    bool has(const char* key) const;
    JsonField operator[](const char* key) const;            // required: fails if missing
    std::optional<JsonField> optional(const char* key) const;
    void allowOnly(const std::vector<std::string_view>& keys) const;
    const JsonField& field() const { return field_; }

private:
    JsonField field_;
};

template <class Enum, size_t N>
Enum JsonField::choice(const std::array<std::pair<std::string_view, Enum>, N>& names) const {
    const std::string text = string();
    std::vector<std::string_view> allowed;
    for (const auto& [name, value] : names) {
        if (name == text) return value;
        allowed.push_back(name);
    }
    failChoice(allowed);
}

}  // namespace shadowlab
