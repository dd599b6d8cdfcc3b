#include "shadows/technique_params.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace shadowlab {

TechniqueParams::TechniqueParams(const std::string& technique, const std::vector<ParamSpec>& specs,
                                 const std::map<std::string, std::string>& given)
    : technique_(technique) {
    for (const ParamSpec& s : specs) values_[s.name] = s.defaultValue;
    for (const auto& [name, value] : given) {
        if (!values_.count(name)) {
            std::string known;
            for (const ParamSpec& s : specs) known += (known.empty() ? "" : ", ") + s.name;
            throw std::invalid_argument("technique '" + technique + "' has no parameter '" + name + "' (" +
                                        (known.empty() ? "it has none" : "known: " + known) + ")");
        }
        values_[name] = value;
    }
}

const std::string& TechniqueParams::raw(const std::string& name) const {
    const auto it = values_.find(name);
    if (it == values_.end()) throw std::logic_error("parameter '" + name + "' was not declared by " + technique_);
    return it->second;
}

void TechniqueParams::fail(const std::string& name, const std::string& why) const {
    throw std::invalid_argument(technique_ + ": parameter " + name + "=" + raw(name) + ": " + why);
}

int TechniqueParams::integer(const std::string& name, int min, int max) const {
    const std::string& text = raw(name);
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) fail(name, "expected an integer");
    if (value < min || value > max) fail(name, "must be in " + std::to_string(min) + ".." + std::to_string(max));
    return value;
}

double TechniqueParams::real(const std::string& name, double min, double max) const {
    const std::string& text = raw(name);
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) fail(name, "expected a finite number");
    if (value < min || value > max) fail(name, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
    return value;
}

bool TechniqueParams::flag(const std::string& name) const {
    return choice(name, {"off", "on"}) == "on";
}

std::string TechniqueParams::choice(const std::string& name, const std::vector<std::string>& choices) const {
    const std::string& text = raw(name);
    std::string list;
    for (const std::string& c : choices) {
        if (c == text) return c;
        list += (list.empty() ? "" : ", ") + c;
    }
    fail(name, "must be one of " + list);
}

void parseParamAssignment(const std::string& text, std::map<std::string, std::string>& into) {
    const size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0) throw std::invalid_argument("--param expects name=value, got '" + text + "'");
    into[text.substr(0, equals)] = text.substr(equals + 1);
}

}  // namespace shadowlab
