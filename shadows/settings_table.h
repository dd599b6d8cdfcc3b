// A technique's settings as one typed struct, bound to its `--param`s by one table: each
// row names a parameter, the member it sets, its range or choices and its help line. The
// specs TechniqueParams checks values against and the code that reads them are then one
// list: a misspelt member does not compile, no name is written twice, and a parameter's
// default is the member's own in a default-constructed struct, so a technique that runs
// another with typed settings (the environment techniques' per-light maps) gets the same
// defaults as the command line.
//
//   const SettingsTable<ShadowMapSettings>& table() {
//       static const auto t = SettingsTable<ShadowMapSettings>()
//           .integer("resolution", member(&ShadowMapSettings::resolution), 16, 8192, "texels per side")
//           .choice("bias", member(&ShadowMapSettings::bias, &BiasSettings::mode), {{"constant", ...}});
//       return t;
//   }
//   const ShadowMapSettings s = table().read(in.params);
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "shadows/technique_params.h"

namespace shadowlab {

// Where a value lives in a settings struct S: a member, or a member of a member.
template <class S, class T>
struct Member {
    std::function<T&(S&)> of;
};

template <class S, class T>
Member<S, T> member(T S::*field) {
    return {[field](S& s) -> T& { return s.*field; }};
}

template <class S, class Sub, class T>
Member<S, T> member(Sub S::*outer, T Sub::*inner) {
    return {[outer, inner](S& s) -> T& { return (s.*outer).*inner; }};
}

// The value itself: the row of a one-value table that several structs include for a
// member of their own (a map's `resolution`, depth_map.h).
template <class T>
Member<T, T> itself() {
    return {[](T& t) -> T& { return t; }};
}

template <class S>
class SettingsTable {
public:
    SettingsTable& integer(std::string name, Member<S, int> at, int min, int max, std::string help) {
        return add(integerParam(std::move(name), 0, min, max, std::move(help)), at,
                   [](const TechniqueParams& p, const std::string& n) { return p.integer(n); },
                   [](int v) { return settingText(v); });
    }

    // An integer in [min, max] or "auto" (empty), which must be the member's default.
    SettingsTable& integerOrAuto(std::string name, Member<S, std::optional<int>> at, int min, int max,
                                 std::string help) {
        return add(integerOrAutoParam(std::move(name), min, max, std::move(help)), at,
                   [](const TechniqueParams& p, const std::string& n) { return p.integerOrAuto(n); },
                   [](const std::optional<int>& v) { return v ? settingText(*v) : std::string("auto"); });
    }

    // A float or double member; the value is read as a double and converted.
    template <class T>
        requires std::is_floating_point_v<T>
    SettingsTable& real(std::string name, Member<S, T> at, double min, double max, std::string help) {
        return add(realParam(std::move(name), 0.0, min, max, std::move(help)), at,
                   [](const TechniqueParams& p, const std::string& n) { return T(p.real(n)); },
                   [](T v) { return settingText(v); });
    }

    // "on" or "off".
    SettingsTable& flag(std::string name, Member<S, bool> at, std::string help) {
        return add(flagParam(std::move(name), false, std::move(help)), at,
                   [](const TechniqueParams& p, const std::string& n) { return p.flag(n); },
                   [](bool v) { return std::string(v ? "on" : "off"); });
    }

    // One of named values of an enum (or bool); the member's default must be one of them.
    template <class E>
    SettingsTable& choice(std::string name, Member<S, E> at, std::vector<Choice<E>> choices, std::string help = "") {
        ParamSpec spec = choiceParam(std::move(name), "", choices, std::move(help));
        return add(std::move(spec), at,
                   [](const TechniqueParams& p, const std::string& n) { return p.choice<E>(n); },
                   [choices](E v) {
                       for (const Choice<E>& c : choices) {
                           if (c.value == v) return c.name;
                       }
                       throw std::logic_error("a settings struct's default is none of its parameter's choices");
                   });
    }

    // Names joined by '+', or "auto" (empty), which must be the member's default.
    SettingsTable& names(std::string name, Member<S, std::optional<std::vector<std::string>>> at, std::string help) {
        return add(namesParam(std::move(name), std::move(help)), at,
                   [](const TechniqueParams& p, const std::string& n) { return p.names(n); },
                   [](const std::optional<std::vector<std::string>>& v) {
                       if (v) throw std::logic_error("a names parameter's default must be auto");
                       return std::string("auto");
                   });
    }

    // Every row of another table, for the part of S it describes (a technique built on
    // another's settings: csm on shadow-map's, PCSS on the map's resolution and bias). The
    // defaults are still S's own, which may differ from Sub's.
    template <class Sub>
    SettingsTable& include(Member<S, Sub> at, const SettingsTable<Sub>& rows) {
        for (const typename SettingsTable<Sub>::Row& row : rows.rows_) {
            rows_.push_back({row.spec, [at, read = row.read](const TechniqueParams& p, S& s) { read(p, at.of(s)); },
                             [at, text = row.defaultText](S& s) { return text(at.of(s)); }});
        }
        return *this;
    }

    // The specs, each with its default from S{} (or from `defaults`, for a technique that
    // shares another's settings but not its defaults), in the order of the rows.
    std::vector<ParamSpec> specs(S defaults = {}) const {
        std::vector<ParamSpec> specs;
        for (const Row& row : rows_) {
            specs.push_back(row.spec);
            specs.back().defaultValue = row.defaultText(defaults);
        }
        return specs;
    }

    // Every row's member set from params, which must have been built from specs().
    S read(const TechniqueParams& params) const {
        S settings{};
        for (const Row& row : rows_) row.read(params, settings);
        return settings;
    }

private:
    template <class>
    friend class SettingsTable;

    struct Row {
        ParamSpec spec;   // its defaultValue set by specs()
        std::function<void(const TechniqueParams&, S&)> read;
        std::function<std::string(S&)> defaultText;
    };

    template <class T, class Get, class Text>
    SettingsTable& add(ParamSpec spec, Member<S, T> at, Get get, Text text) {
        const std::string name = spec.name;
        rows_.push_back({std::move(spec), [at, get, name](const TechniqueParams& p, S& s) { at.of(s) = get(p, name); },
                         [at, text](S& s) { return text(at.of(s)); }});
        return *this;
    }

    std::vector<Row> rows_;
};

}  // namespace shadowlab
