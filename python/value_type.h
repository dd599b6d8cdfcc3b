// An immutable value type for Python, as a frozen dataclass is: its fields read-only (a write
// is an AttributeError that names the fix), made with keyword arguments, replace(**changes)
// for a changed copy, ==, hash, repr and pickling. Every value made or replaced is checked by
// the library's rule for it (scenes/view_rules.h), a ValueError with its one-line message.
// Camera and Light use it (view_bindings.cpp).
#pragma once

#include <algorithm>
#include <cctype>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "scenes/view_rules.h"

namespace shadowlab::python {

template <class T>
struct ValueField {
    const char* name;                 // Python's: "cone_angle"
    const char* key;                  // the scene format's, as a FieldProblem names it: "coneAngle"
    const char* doc;
    std::function<pybind11::object(const T&)> get;
    std::function<void(T&, pybind11::handle)> set;
};

// A field that is a member of T, converted as pybind11 converts V.
template <class T, class V>
ValueField<T> memberField(const char* name, const char* key, V T::*member, const char* doc) {
    return {name, key, doc, [member](const T& value) { return pybind11::cast(value.*member); },
            [member](T& value, pybind11::handle given) { value.*member = given.cast<V>(); }};
}

template <class T>
struct ValueType {
    const char* name;   // "Camera"
    std::vector<ValueField<T>> fields;
    std::function<std::optional<FieldProblem>(const T&)> problem;
    // A FieldProblem's key that no field has, and the field it belongs to: a disk's "normal" is "direction".
    std::vector<std::pair<const char*, const char*>> keyAliases = {};
    // What == compares besides the fields (a light's cookie), and what pickling cannot keep.
    std::function<bool(const T&, const T&)> sameRest = [](const T&, const T&) { return true; };
    std::function<bool(const T&)> pickles = [](const T&) { return true; };
};

// "Camera" -> "camera": how a variable holding one is called in a message.
inline std::string lowered(std::string name) {
    for (char& c : name) c = char(std::tolower((unsigned char)c));
    return name;
}

template <class T>
std::string fieldNameOf(const ValueType<T>& type, std::string_view key) {
    for (const auto& [alias, field] : type.keyAliases)
        if (key == alias) key = field;
    for (const ValueField<T>& field : type.fields)
        if (key == field.key) return field.name;
    return std::string(key);
}

// std::invalid_argument (a ValueError) with the rule's message, for a value that breaks it.
template <class T>
void requireValid(const ValueType<T>& type, const T& value) {
    if (const auto problem = type.problem(value))
        throw std::invalid_argument(std::string(type.name) + "." + fieldNameOf(type, problem->field) + ": " +
                                    problem->problem);
}

// base with the fields named in changes set, checked.
template <class T>
T changed(const ValueType<T>& type, T value, const pybind11::dict& changes) {
    for (const auto& [key, given] : changes) {
        const std::string name = pybind11::str(key);
        const auto field = std::find_if(type.fields.begin(), type.fields.end(),
                                        [&](const ValueField<T>& f) { return name == f.name; });
        if (field == type.fields.end())
            throw pybind11::type_error(std::string(type.name) + " has no field \"" + name + "\"");
        try {
            field->set(value, given);
        } catch (const pybind11::cast_error&) {
            throw pybind11::type_error(std::string(type.name) + "." + name + ": cannot be " +
                                       std::string(pybind11::str(pybind11::type::handle_of(given).attr("__name__"))));
        }
    }
    requireValid(type, value);
    return value;
}

template <class T>
pybind11::tuple fieldValues(const ValueType<T>& type, const T& value) {
    pybind11::tuple values(type.fields.size());
    for (size_t k = 0; k < type.fields.size(); ++k) values[k] = type.fields[k].get(value);
    return values;
}

template <class T>
void bindValueType(pybind11::class_<T>& cls, std::shared_ptr<const ValueType<T>> type, const std::string& initDoc) {
    namespace py = pybind11;
    cls.def(py::init([type](const py::kwargs& fields) { return changed(*type, T{}, fields); }), initDoc.c_str());
    for (const ValueField<T>& field : type->fields) {
        const std::string name = field.name;
        cls.def_property(
            field.name, field.get,
            [type, name](T&, py::handle given) {
                throw py::attribute_error(std::string(type->name) + " is a value: use " + lowered(type->name) +
                                          ".replace(" + name + "=" + std::string(py::repr(given)) +
                                          ") and assign it back");
            },
            field.doc);
    }
    cls.def(
        "replace", [type](const T& value, const py::kwargs& changes) { return changed(*type, value, changes); },
        "A copy with the fields given changed, checked (ValueError); this one is left as it is (dataclasses.replace).");
    cls.def("__eq__", [type](const T& a, const T& b) {
        return fieldValues(*type, a).equal(fieldValues(*type, b)) && type->sameRest(a, b);
    });
    cls.def("__hash__", [type](const T& value) { return py::hash(fieldValues(*type, value)); });
    cls.def("__copy__", [](const T& value) { return value; });
    cls.def("__deepcopy__", [](const T& value, const py::dict&) { return value; });
    cls.def("__repr__", [type](const T& value) {
        std::string text = std::string(type->name) + "(";
        for (size_t k = 0; k < type->fields.size(); ++k)
            text += (k ? ", " : "") + std::string(type->fields[k].name) + "=" +
                    std::string(py::repr(type->fields[k].get(value)));
        return text + ")";
    });
    cls.def(py::pickle(
        [type](const T& value) {
            if (!type->pickles(value)) throw std::invalid_argument(std::string(type->name) + " with a cookie does not pickle");
            py::dict fields;
            for (const ValueField<T>& field : type->fields) fields[field.name] = field.get(value);
            return fields;
        },
        [type](const py::dict& fields) { return changed(*type, T{}, fields); }));
}

}  // namespace shadowlab::python
