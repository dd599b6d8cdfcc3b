// The tolerance of receiver-plane bias (shadow_bias.h), shared by the double lookup
// (shadow_bias.cpp) and the float one (lookup_kernel.inl). Plain constants only: the
// per-instruction-set kernels include it.
//
// The rasterizer snaps vertices to 1/256 texel (docs/rasterizer.md, "Setup"), so a stored depth is the
// depth of a plane through vertices moved by up to 1/512 texel in x and y: at most
// (|dz/dx| + |dz/dy|) / 512 away from the true plane there. The float transform of the
// vertices adds well under 1e-3 texel at 8192 texels. Twice the snapping bound covers both.
// Window depth is stored as float (2^-24 steps just below 1) after a float matrix product
// whose terms can exceed the result ten-fold; 16 steps of 2^-24 bound that rounding, and
// the float lookup's own projection of the receiver, measured at under 4 steps
// (test_lookup_kernel.cpp).
#pragma once

namespace shadowlab::receiver_plane {

inline constexpr double kRasterPositionErrorTexels = 1.0 / 256.0;
inline constexpr double kDepthErrorSteps = 16.0;
inline constexpr double kDepthStep = 1.0 / 16777216.0;   // 2^-24, window depth units

}  // namespace shadowlab::receiver_plane
