// Chebyshev's one-sided inequality as the variance-based shadow maps use it (Real-Time
// Rendering, 4th ed., eqs. 7.7 and 7.8; Donnelly and Lauritzen 2006): vsm.cpp on the depth,
// evsm.cpp on its two exponential warps.
#pragma once

#include <algorithm>

namespace shadowlab {

// The smallest variance Chebyshev's bound uses, in normalised depth units squared
// (Donnelly and Lauritzen 2006, section 3.2: "clamp the variance to a minimum" against
// rounding). 1e-7 is a depth spread of 3e-4 of the light's range, about 4 mm over the
// built-in scenes' 14 m: far below one texel's depth slope on any lit receiver, far above
// the double rounding of M2 - M1^2 (2^-52).
inline constexpr double kMinVariance = 1e-7;

// The largest fraction of a distribution with mean m1 and second moment m2 that can lie at
// or beyond t.
inline double chebyshevUpperBound(double m1, double m2, double t, double minVariance) {
    if (t <= m1) return 1.0;
    const double variance = std::max(m2 - m1 * m1, minVariance);
    const double d = t - m1;
    return variance / (variance + d * d);
}

}  // namespace shadowlab
