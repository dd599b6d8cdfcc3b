#include "scenes/json_fields.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scenes/error_text.h"
#include "scenes/float_range.h"
#include "scenes/scene_error.h"
#include "scenes/scene_limits.h"

namespace shadowlab {
namespace {

// "file: path: problem", or "file: problem" at the top level.
std::string located(const std::string& file, const std::string& path, const std::string& problem) {
    return file + ": " + (path.empty() ? "" : path + ": ") + problem;
}

std::string joinNames(const std::vector<std::string_view>& names) {
    std::string joined;
    for (std::string_view name : names) {
        joined += joined.empty() ? "" : ", ";
        joined += name;
    }
    return joined;
}

// A short rendering of the offending value for error messages.
std::string excerpt(const nlohmann::json& value) {
    const std::string text = value.dump();
    constexpr size_t kMaxChars = 40;
    return text.size() <= kMaxChars ? text : text.substr(0, kMaxChars) + "...";
}

// Follows the parser through the document, so that an error nlohmann raises itself can
// name the field being read like every other error. Containers produce start and end
// events, scalars a value event; keys arrive before their values.
class PathTracker {
public:
    void onEvent(nlohmann::json::parse_event_t event, const nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        switch (event) {
            case Event::object_start: levels_.push_back({false, "", 0}); break;
            case Event::array_start: levels_.push_back({true, "", 0}); break;
            case Event::key: levels_.back().key = parsed.get<std::string>(); break;
            case Event::object_end:
            case Event::array_end:
                levels_.pop_back();
                elementDone();
                break;
            case Event::value: elementDone(); break;
        }
    }

    std::string path() const {
        std::string path;
        for (const Level& level : levels_) {
            if (level.isArray) path += "[" + std::to_string(level.index) + "]";
            else if (!level.key.empty()) path += (path.empty() ? "" : ".") + level.key;
        }
        return path;
    }

private:
    struct Level {
        bool isArray;
        std::string key;   // objects: the key being read
        size_t index;      // arrays: elements read so far
    };

    void elementDone() {
        if (!levels_.empty() && levels_.back().isArray) ++levels_.back().index;
    }

    std::vector<Level> levels_;
};

}  // namespace

nlohmann::json parseJson(const std::string& text, const std::string& file) {
    PathTracker tracker;
    try {
        return nlohmann::json::parse(text, [&](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
            // Refused while parsing: a deeper document would only ever be an attack on the
            // recursive code that reads and prints JSON (a scene needs 4 levels).
            if (depth > kMaxJsonDepth)
                throw SceneError(located(file, tracker.path(), "nested deeper than " + std::to_string(kMaxJsonDepth) + " levels"));
            tracker.onEvent(event, parsed);
            return true;
        });
    } catch (const nlohmann::json::exception& error) {
        throw SceneError(located(file, tracker.path(), std::string("invalid JSON: ") + error.what()));
    }
}

std::string formatNumber(double x) {
    std::ostringstream out;
    out << x;
    return out.str();
}

bool Interval::contains(double x) const {
    const bool aboveLo = loOpen ? x > lo : x >= lo;
    const bool belowHi = hiOpen ? x < hi : x <= hi;
    return aboveLo && belowHi;
}

std::string Interval::describe() const {
    if (std::isinf(hi)) return (loOpen ? "> " : ">= ") + formatNumber(lo);
    return std::string("in ") + (loOpen ? "(" : "[") + formatNumber(lo) + ", " +
           formatNumber(hi) + (hiOpen ? ")" : "]");
}

JsonField::JsonField(const nlohmann::json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

void JsonField::fail(const std::string& problem) const {
    throw SceneError(located(file_, path_, problem));
}

void JsonField::fail(const SceneError& cause) const {
    if (dynamic_cast<const MissingFileError*>(&cause)) throw MissingFileError(located(file_, path_, cause.what()));
    fail(cause.what());
}

void JsonField::failType(const char* expected) const {
    fail(std::string("must be ") + expected + ", got " + excerpt(*value_));
}

void JsonField::failChoice(const std::vector<std::string_view>& allowed) const {
    fail("unknown value " + excerpt(*value_) + " (allowed: " + joinNames(allowed) + ")");
}

JsonField JsonField::child(std::string path, const nlohmann::json& value) const {
    return JsonField(value, file_, std::move(path));
}

float JsonField::number(Interval range) const {
    if (!value_->is_number()) failType("a number");
    const double x = value_->get<double>();
    // JSON has no NaN, but "1e999" parses to infinity, and a finite double can still
    // overflow the float that the renderer stores.
    if (!roundsToFiniteFloat(x))
        fail("must be a finite number within float range, got " + formatNumber(x));
    if (!range.contains(x)) fail("must be " + range.describe() + ", got " + formatNumber(x));
    return float(x);
}

int JsonField::integer(Interval range) const {
    if (!value_->is_number_integer()) failType("an integer");
    const double x = value_->get<double>();
    if (!range.contains(x)) fail("must be " + range.describe() + ", got " + excerpt(*value_));
    return int(x);
}

bool JsonField::boolean() const {
    if (!value_->is_boolean()) failType("true or false");
    return value_->get<bool>();
}

std::string JsonField::string() const {
    if (!value_->is_string()) failType("a string");
    return value_->get<std::string>();
}

glm::vec3 JsonField::vec3(Interval range) const {
    const std::vector<JsonField> xyz = elements(3);
    return {xyz[0].number(range), xyz[1].number(range), xyz[2].number(range)};
}

std::vector<JsonField> JsonField::elements() const {
    if (!value_->is_array()) failType("an array");
    std::vector<JsonField> items;
    for (size_t i = 0; i < value_->size(); ++i)
        items.push_back(child(path_ + "[" + std::to_string(i) + "]", (*value_)[i]));
    return items;
}

std::vector<JsonField> JsonField::elements(size_t count) const {
    if (!value_->is_array() || value_->size() != count)
        failType(("an array of " + std::to_string(count) + " numbers").c_str());
    return elements();
}

JsonObject JsonField::object() const {
    if (!value_->is_object()) failType("an object");
    return JsonObject(*this);
}

JsonObject JsonField::object(const std::vector<std::string_view>& allowedKeys) const {
    JsonObject result = object();
    result.allowOnly(allowedKeys);
    return result;
}

JsonObject::JsonObject(JsonField field) : field_(std::move(field)) {}

bool JsonObject::has(const char* key) const {
    return field_.value_->contains(key);
}

JsonField JsonObject::operator[](const char* key) const {
    if (!has(key)) field_.fail(std::string("missing required field \"") + key + "\"");
    return *optional(key);
}

std::optional<JsonField> JsonObject::optional(const char* key) const {
    if (!has(key)) return std::nullopt;
    const std::string path = field_.path_.empty() ? key : field_.path_ + "." + key;
    return field_.child(path, field_.value_->at(key));
}

void JsonObject::allowOnly(const std::vector<std::string_view>& keys) const {
    for (const auto& [key, value] : field_.value_->items()) {
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            field_.fail("unknown key " + inQuotes(key) + " (allowed: " + joinNames(keys) + ")");
    }
}

}  // namespace shadowlab
