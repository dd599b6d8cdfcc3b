// Every technique of every family, by name: the one file above the families that lists
// them all (docs/architecture.md), so that no file under shadows/ includes every family.
#pragma once

#include <string>
#include <vector>

#include "shadows/technique.h"

namespace shadowlab {

// In the order `shadowlab techniques` lists them.
const std::vector<Technique>& techniques();
// Throws std::invalid_argument naming the known techniques.
const Technique& findTechnique(const std::string& name);

}  // namespace shadowlab
