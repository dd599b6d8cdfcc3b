// The source set of Gibson et al. 2003 (section 4): every patch with radiance may light the
// scene, but only the brightest matter. The patches are sorted by decreasing radiance and
// the source set is the shortest run from the top whose power reaches a share of all the
// patches' power (70% "accounts for all primary and important secondary sources of light"),
// and every other patch as bright as the last of it: the set is all the patches above a
// radiance, so a light of one radiance is in it whole or not at all, however finely it is
// cut (the sorted order alone would keep the first of its patches and leave the others).
// A Lambertian patch of radiance L and area A emits the power pi L A.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace shadowlab {

struct EmittingPatch {
    double radiance = 0.0;   // luminance of its radiance, W/(m^2 sr)
    double area = 0.0;       // m^2
};

// The indices of the source set, brightest first (ties by index); none when no patch
// emits. Throws std::invalid_argument for a share outside (0, 1], or a negative or
// non-finite radiance or area.
std::vector<uint32_t> selectSources(std::span<const EmittingPatch> patches, double share = 0.7);

}  // namespace shadowlab
