// The checks of Camera and Light (view_bindings.cpp) for what holds them: prepare() checks a
// whole scene with them, as a value made in Python is checked where it is made.
#pragma once

#include <vector>

#include "scenes/scene.h"

namespace shadowlab::python {

// std::invalid_argument (a ValueError) with the rule's message (scenes/view_rules.h).
void requireValid(const Camera& camera);
void requireValid(const std::vector<Light>& lights);   // each, and their number

}  // namespace shadowlab::python
