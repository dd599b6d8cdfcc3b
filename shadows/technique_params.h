// Level-of-detail settings of a technique (`--param name=value`, and the axes of
// `shadowlab sweep`). Each technique declares its parameters as specs: a type, a default, a
// range or a list of choices, and a help line. A spec is the one place these are written:
// the help `shadowlab techniques` prints and the check of every value both come from it.
// Values are checked when TechniqueParams is built, so a technique reads them unchecked.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace shadowlab {

enum class ParamType { Integer, Real, Flag, Choice, Names };

// One allowed value of a choice parameter: its name, the enumerator (or bool) it stands
// for, and what it means where the name does not say.
template <class E>
struct Choice {
    std::string name;
    E value;
    std::string help = "";
};

// A Choice as a spec keeps it: the enumerator as an int.
struct ParamChoice {
    std::string name;
    int value = 0;
    std::string help;
};

struct ParamSpec {
    std::string name;
    ParamType type = ParamType::Integer;
    std::string defaultValue;                     // as it would be given on the command line
    std::string help;                             // what it sets; the range or choices follow
    double min = 0.0, max = 0.0;                  // Integer, Real: the closed range allowed
    bool orAuto = false;                          // Integer: "auto" is allowed too
    std::vector<ParamChoice> choices = {};        // Choice
    const std::type_info* choiceType = nullptr;   // Choice: the type of the values
};

// A value as `--param` takes it and `shadowlab techniques` prints it: for a number, the
// shortest text that reads back as the same float or double, exponent unpadded ("0.05", not
// the double nearest 0.05f; "8192", "1e-4").
std::string settingText(int value);
std::string settingText(double value);
std::string settingText(float value);

ParamSpec integerParam(std::string name, int defaultValue, int min, int max, std::string help);
// An integer in [min, max] or "auto" (the default): the technique chooses.
ParamSpec integerOrAutoParam(std::string name, int min, int max, std::string help);
ParamSpec realParam(std::string name, double defaultValue, double min, double max, std::string help);
// "on" or "off".
ParamSpec flagParam(std::string name, bool defaultValue, std::string help);
ParamSpec choiceParam(std::string name, std::string defaultChoice, std::vector<ParamChoice> choices,
                      const std::type_info& choiceType, std::string help);
// A list of names joined by '+' ("box+sphere", each name non-empty, no '=' or ','), or
// "auto" (the default): the technique chooses. Scene instance names, for example.
ParamSpec namesParam(std::string name, std::string help);

template <class E>
ParamSpec choiceParam(std::string name, std::string defaultChoice, const std::vector<Choice<E>>& choices,
                      std::string help = "") {
    std::vector<ParamChoice> stored;
    for (const Choice<E>& c : choices) stored.push_back({c.name, static_cast<int>(c.value), c.help});
    return choiceParam(std::move(name), std::move(defaultChoice), std::move(stored), typeid(E), std::move(help));
}

// The help line of `shadowlab techniques`: the spec's help with its range ("texels per side
// of each map (16..8192)") or its choices ("filter=blur: box | gaussian (sigma = width / 6)").
std::string paramHelp(const ParamSpec& spec);

class TechniqueParams {
public:
    // Throws std::invalid_argument naming the technique, the parameter and what it allows for
    // a given name not in `specs` or a given value the spec does not allow; std::logic_error
    // for a default the spec does not allow, or a name declared twice.
    TechniqueParams(const std::string& technique, const std::vector<ParamSpec>& specs,
                    const std::map<std::string, std::string>& given);

    // The value of a declared parameter of that type; anything else is a bug in the
    // technique and throws std::logic_error.
    int integer(const std::string& name) const;
    std::optional<int> integerOrAuto(const std::string& name) const;   // empty for "auto"
    double real(const std::string& name) const;
    bool flag(const std::string& name) const;
    std::optional<std::vector<std::string>> names(const std::string& name) const;   // empty for "auto"
    template <class E>
    E choice(const std::string& name) const {
        return static_cast<E>(choiceValue(name, typeid(E)));
    }

    // Every parameter with its value, defaults included, in name order (for reports).
    const std::map<std::string, std::string>& values() const { return values_; }

private:
    // The spec of `name`, which must have been declared with this type.
    const ParamSpec& spec(const std::string& name, ParamType type, bool orAuto = false,
                          const std::type_info* choiceType = nullptr) const;
    int choiceValue(const std::string& name, const std::type_info& type) const;

    std::string technique_;
    std::map<std::string, ParamSpec> specs_;
    std::map<std::string, std::string> values_;
};

// Parses "name=value" into the map; throws std::invalid_argument without '=' or a name.
void parseParamAssignment(const std::string& text, std::map<std::string, std::string>& into);

}  // namespace shadowlab
