#include "shadows/technique_params.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace shadowlab {
namespace {

constexpr const char* kAuto = "auto";

template <class T>
std::string shortestText(T value) {
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text(buffer, end);
    const size_t e = text.find('e');
    if (e == std::string::npos) return text;
    size_t digits = e + 1;
    if (text[digits] == '+') text.erase(digits, 1);
    if (text[digits] == '-') ++digits;
    while (text[digits] == '0' && digits + 1 < text.size()) text.erase(digits, 1);
    return text;
}

template <class T>
std::optional<T> parseNumber(const std::string& text) {
    T value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

// The names of a Names value, split at '+'.
std::vector<std::string> splitNames(const std::string& text) {
    std::vector<std::string> names;
    size_t begin = 0;
    for (size_t plus = text.find('+'); plus != std::string::npos; begin = plus + 1, plus = text.find('+', begin)) {
        names.push_back(text.substr(begin, plus - begin));
    }
    names.push_back(text.substr(begin));
    return names;
}

bool allowsNames(const std::string& text) {
    if (text == kAuto) return true;
    for (const std::string& name : splitNames(text)) {
        if (name.empty() || name.find_first_of("=,") != std::string::npos) return false;
    }
    return true;
}

const ParamChoice* findChoice(const ParamSpec& spec, const std::string& text) {
    for (const ParamChoice& c : spec.choices) {
        if (c.name == text) return &c;
    }
    return nullptr;
}

std::string rangeText(const ParamSpec& spec) {
    return settingText(spec.min) + ".." + settingText(spec.max) + (spec.orAuto ? std::string(" or ") + kAuto : "");
}

std::string choiceList(const ParamSpec& spec, const std::string& separator, bool withHelp) {
    std::string list;
    for (const ParamChoice& c : spec.choices) {
        list += (list.empty() ? "" : separator) + c.name;
        if (withHelp && !c.help.empty()) list += " (" + c.help + ")";
    }
    return list;
}

// What the spec allows, as the end of "must be ...".
std::string allowedText(const ParamSpec& spec) {
    switch (spec.type) {
        case ParamType::Integer: return "an integer in " + rangeText(spec);
        case ParamType::Real: return "a finite number in " + rangeText(spec);
        case ParamType::Flag: return "on or off";
        case ParamType::Choice: return "one of " + choiceList(spec, ", ", false);
        case ParamType::Names: return std::string(kAuto) + " or names joined by '+', none empty, without '=' or ','";
    }
    return "";
}

bool inRange(const ParamSpec& spec, double value) { return value >= spec.min && value <= spec.max; }

bool allows(const ParamSpec& spec, const std::string& text) {
    switch (spec.type) {
        case ParamType::Integer: {
            if (spec.orAuto && text == kAuto) return true;
            const std::optional<int> value = parseNumber<int>(text);
            return value && inRange(spec, *value);
        }
        case ParamType::Real: {
            const std::optional<double> value = parseNumber<double>(text);
            return value && std::isfinite(*value) && inRange(spec, *value);
        }
        case ParamType::Flag: return text == "on" || text == "off";
        case ParamType::Choice: return findChoice(spec, text) != nullptr;
        case ParamType::Names: return allowsNames(text);
    }
    return false;
}

}  // namespace

std::string settingText(int value) { return std::to_string(value); }
std::string settingText(double value) { return shortestText(value); }
std::string settingText(float value) { return shortestText(value); }

ParamSpec integerParam(std::string name, int defaultValue, int min, int max, std::string help) {
    return {.name = std::move(name), .type = ParamType::Integer, .defaultValue = std::to_string(defaultValue),
            .help = std::move(help), .min = double(min), .max = double(max)};
}

ParamSpec integerOrAutoParam(std::string name, int min, int max, std::string help) {
    return {.name = std::move(name), .type = ParamType::Integer, .defaultValue = kAuto, .help = std::move(help),
            .min = double(min), .max = double(max), .orAuto = true};
}

ParamSpec realParam(std::string name, double defaultValue, double min, double max, std::string help) {
    return {.name = std::move(name), .type = ParamType::Real, .defaultValue = settingText(defaultValue),
            .help = std::move(help), .min = min, .max = max};
}

ParamSpec flagParam(std::string name, bool defaultValue, std::string help) {
    return {.name = std::move(name), .type = ParamType::Flag, .defaultValue = defaultValue ? "on" : "off",
            .help = std::move(help)};
}

ParamSpec choiceParam(std::string name, std::string defaultChoice, std::vector<ParamChoice> choices,
                      const std::type_info& choiceType, std::string help) {
    return {.name = std::move(name), .type = ParamType::Choice, .defaultValue = std::move(defaultChoice),
            .help = std::move(help), .choices = std::move(choices), .choiceType = &choiceType};
}

ParamSpec namesParam(std::string name, std::string help) {
    return {.name = std::move(name), .type = ParamType::Names, .defaultValue = kAuto, .help = std::move(help)};
}

std::string paramHelp(const ParamSpec& spec) {
    const std::string help = spec.help.empty() ? "" : spec.help + " ";
    switch (spec.type) {
        case ParamType::Integer:
        case ParamType::Real: return help + "(" + rangeText(spec) + ")";
        case ParamType::Flag: return help + "(on | off)";
        case ParamType::Choice: return (spec.help.empty() ? "" : spec.help + ": ") + choiceList(spec, " | ", true);
        case ParamType::Names: return help + "(auto | name+name+...)";
    }
    return spec.help;
}

TechniqueParams::TechniqueParams(const std::string& technique, const std::vector<ParamSpec>& specs,
                                 const std::map<std::string, std::string>& given)
    : technique_(technique) {
    for (const ParamSpec& s : specs) {
        if (!specs_.emplace(s.name, s).second) throw std::logic_error(technique + " declares parameter " + s.name + " twice");
        if (!allows(s, s.defaultValue)) {
            throw std::logic_error(technique + ": the default " + s.name + "=" + s.defaultValue + " is not " + allowedText(s));
        }
        values_[s.name] = s.defaultValue;
    }
    for (const auto& [name, value] : given) {
        const auto it = specs_.find(name);
        if (it == specs_.end()) {
            std::string known;
            for (const ParamSpec& s : specs) known += (known.empty() ? "" : ", ") + s.name;
            throw std::invalid_argument("technique '" + technique + "' has no parameter '" + name + "' (" +
                                        (known.empty() ? "it has none" : "known: " + known) + ")");
        }
        if (!allows(it->second, value)) {
            throw std::invalid_argument(technique + ": parameter " + name + "=" + value + ": must be " + allowedText(it->second));
        }
        values_[name] = value;
    }
}

const ParamSpec& TechniqueParams::spec(const std::string& name, ParamType type, bool orAuto,
                                       const std::type_info* choiceType) const {
    const auto it = specs_.find(name);
    if (it == specs_.end()) throw std::logic_error("parameter '" + name + "' was not declared by " + technique_);
    const ParamSpec& s = it->second;
    if (s.type != type || s.orAuto != orAuto || (choiceType && *s.choiceType != *choiceType)) {
        throw std::logic_error(technique_ + " reads parameter '" + name + "' as another type than it declared");
    }
    return s;
}

int TechniqueParams::integer(const std::string& name) const {
    spec(name, ParamType::Integer);
    return *parseNumber<int>(values_.at(name));
}

std::optional<int> TechniqueParams::integerOrAuto(const std::string& name) const {
    spec(name, ParamType::Integer, true);
    const std::string& text = values_.at(name);
    return text == kAuto ? std::nullopt : parseNumber<int>(text);
}

double TechniqueParams::real(const std::string& name) const {
    spec(name, ParamType::Real);
    return *parseNumber<double>(values_.at(name));
}

bool TechniqueParams::flag(const std::string& name) const {
    spec(name, ParamType::Flag);
    return values_.at(name) == "on";
}

std::optional<std::vector<std::string>> TechniqueParams::names(const std::string& name) const {
    spec(name, ParamType::Names);
    const std::string& text = values_.at(name);
    if (text == kAuto) return std::nullopt;
    return splitNames(text);
}

int TechniqueParams::choiceValue(const std::string& name, const std::type_info& type) const {
    return findChoice(spec(name, ParamType::Choice, false, &type), values_.at(name))->value;
}

void parseParamAssignment(const std::string& text, std::map<std::string, std::string>& into) {
    const size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0) throw std::invalid_argument("--param expects name=value, got '" + text + "'");
    into[text.substr(0, equals)] = text.substr(equals + 1);
}

}  // namespace shadowlab
