// Level-of-detail settings of a technique (`--param name=value`, and the axes of
// `shadowlab sweep`). Each technique declares its parameters with defaults; reading one
// checks its type and range, and an unknown name is an error that lists the known ones.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace shadowlab {

struct ParamSpec {
    std::string name;
    std::string defaultValue;
    std::string help;
};

class TechniqueParams {
public:
    TechniqueParams() = default;
    // Throws std::invalid_argument for a name not in `specs`.
    TechniqueParams(const std::string& technique, const std::vector<ParamSpec>& specs,
                    const std::map<std::string, std::string>& given);

    // Each throws std::invalid_argument naming the technique and parameter when the value is
    // not of the type or outside [min, max] (or not one of `choices`).
    int integer(const std::string& name, int min, int max) const;
    double real(const std::string& name, double min, double max) const;
    bool flag(const std::string& name) const;
    std::string choice(const std::string& name, const std::vector<std::string>& choices) const;

    // Every parameter with its value, defaults included, in name order (for reports).
    const std::map<std::string, std::string>& values() const { return values_; }

private:
    const std::string& raw(const std::string& name) const;
    [[noreturn]] void fail(const std::string& name, const std::string& why) const;

    std::string technique_;
    std::map<std::string, std::string> values_;
};

// Parses "name=value" into the map; throws std::invalid_argument without '=' or a name.
void parseParamAssignment(const std::string& text, std::map<std::string, std::string>& into);

}  // namespace shadowlab
