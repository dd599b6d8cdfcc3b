// Technique and Param: the registry's techniques (frame/registry.h) with their typed
// parameters (shadows/technique_params.h), as `shadowlab techniques` lists them.
#include <string>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "frame/registry.h"
#include "python/bindings.h"
#include "shadows/technique.h"
#include "shadows/technique_params.h"

namespace py = pybind11;

namespace shadowlab::python {
namespace {

const char* typeName(ParamType type) {
    switch (type) {
        case ParamType::Integer: return "integer";
        case ParamType::Real: return "real";
        case ParamType::Flag: return "flag";
        case ParamType::Choice: return "choice";
        case ParamType::Names: return "names";
    }
    return "";
}

// A setting's text as a Python value: an int, a float or a bool where the type says so and
// the text is not "auto"; otherwise the text.
py::object settingValue(const ParamSpec& spec, const std::string& text) {
    if (text == "auto") return py::str(text);
    switch (spec.type) {
        case ParamType::Integer: return py::int_(std::stoi(text));
        case ParamType::Real: return py::float_(std::stod(text));
        case ParamType::Flag: return py::bool_(text == "on");
        case ParamType::Choice:
        case ParamType::Names: break;
    }
    return py::str(text);
}

py::object rangeEnd(const ParamSpec& spec, double end) {
    if (spec.type == ParamType::Integer) return py::int_(int(end));
    if (spec.type == ParamType::Real) return py::float_(end);
    return py::none();
}

std::vector<std::string> choiceNames(const ParamSpec& spec) {
    std::vector<std::string> names;
    for (const ParamChoice& c : spec.choices) names.push_back(c.name);
    return names;
}

void bindParam(py::module_& m) {
    py::class_<ParamSpec>(m, "Param", "A technique's parameter (a setting of render()'s params).")
        .def_readonly("name", &ParamSpec::name, "its name, as params and --param give it")
        .def_property_readonly(
            "type", [](const ParamSpec& s) { return typeName(s.type); },
            "\"integer\", \"real\", \"flag\" (a bool), \"choice\" or \"names\" (names joined by '+')")
        .def_property_readonly(
            "default", [](const ParamSpec& s) { return settingValue(s, s.defaultValue); },
            "its default: an int, float or bool by its type, else a str (\"auto\" too)")
        .def_readonly("default_text", &ParamSpec::defaultValue, "its default as --param text")
        .def_property_readonly("help", &paramHelp, "the help line of `shadowlab techniques`, with the range or choices")
        .def_property_readonly(
            "min", [](const ParamSpec& s) { return rangeEnd(s, s.min); }, "integer, real: the smallest value allowed; else None")
        .def_property_readonly(
            "max", [](const ParamSpec& s) { return rangeEnd(s, s.max); }, "integer, real: the largest value allowed; else None")
        .def_readonly("or_auto", &ParamSpec::orAuto, "integer: whether \"auto\" is allowed too")
        .def_property_readonly("choices", &choiceNames, "choice: the names allowed; else empty")
        .def("__repr__", [](const ParamSpec& s) { return "<Param " + s.name + ": " + paramHelp(s) + ">"; });
}

void bindTechnique(py::module_& m) {
    py::class_<Technique>(m, "Technique", "A shadow technique of the library (techniques(), technique(name)).")
        .def_readonly("name", &Technique::name, "its name, as render() and --technique take it")
        .def_readonly("description", &Technique::description, "one line")
        .def_readonly("reference", &Technique::referenceName,
                      "the technique it is scored against: \"reference\" or \"reference-soft\"")
        .def_property_readonly(
            "output", [](const Technique& t) { return t.output == TechniqueOutput::Visibility ? "visibility" : "radiance"; },
            "\"visibility\" (its V, which the frame shades) or \"radiance\" (its own shaded image)")
        .def_readonly("temporal", &Technique::temporal, "whether a frame depends on the frames before (FrameHistory)")
        .def_readonly("params", &Technique::params, "its parameters, a list of Param")
        .def("__repr__", [](const Technique& t) { return "<Technique " + t.name + ">"; });
}

}  // namespace

void bindTechniques(py::module_& m) {
    bindParam(m);
    bindTechnique(m);
    m.def("techniques", &techniques, py::return_value_policy::reference,
          "Every technique, in the order `shadowlab techniques` lists them.");
    m.def("technique", &findTechnique, py::arg("name"), py::return_value_policy::reference,
          "The technique of that name; ValueError naming the known ones for another.");
}

}  // namespace shadowlab::python
