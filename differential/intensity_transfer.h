// Intensity transfers for compositing shadows into an 8-bit photograph (Gibson et al. 2003,
// section 7.1, equations 3 and 4, and the estimate of Figure 4). Differential rendering in
// radiance takes sum_j L_ij M_ij off the radiance L_i at receiver vertex i (equation 2), but
// a photograph holds pixel intensities I_i = T(L_i) under the camera's non-linear response
// T. The intensity transfer S_ij is what pass j must take off the intensity instead, so
// that I_i - sum_j S_ij M_ij = T(L_i - sum_j L_ij M_ij) (equation 3). Which sources are
// occluded (M) is not known when the S_ij are made, so Figure 4 assumes the sources fall
// into two sets, each occluded whole while the other stays visible: each source is taken
// off the running radiance of its set, and its S_ij is the fall in T that causes. The
// estimate is exact when the occluded sources are one of the two sets, and close when few
// are occluded (Figure 3); sources go in order of decreasing transfer, so that the
// brightest are taken first in every frame.
#pragma once

#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace shadowlab {

// Figure 4 for one receiver vertex: its total radiance towards the camera `total` (L_i),
// the transfers of its sources in pass order (L_ij), each source's set (0 or 1: even or odd
// id in the paper), and the response T (radiance -> intensity, per channel, monotone),
// into S (S_ij, one per source).
template <class Response>
void intensityTransfers(const glm::dvec3& total, std::span<const glm::dvec3> transfers, std::span<const uint8_t> set,
                        const Response& T, std::span<glm::dvec3> S) {
    glm::dvec3 radiance[2] = {total, total};
    glm::dvec3 intensity[2] = {T(total), T(total)};
    for (size_t j = 0; j < transfers.size(); ++j) {
        const int s = set[j];
        radiance[s] -= transfers[j];
        const glm::dvec3 after = T(radiance[s]);
        S[j] = intensity[s] - after;
        intensity[s] = after;
    }
}

}  // namespace shadowlab
