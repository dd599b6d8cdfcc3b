// The texel a coordinate falls in, for every map and page (depth_map.h, the virtual map's
// pages): plain data, no library call.
#pragma once

namespace shadowlab {

// The texel holding texel coordinate c, floor(c), saturated to +-2^30 (NaN to -2^30) so
// that any coordinate is a valid int that a map's at() then clamps (converting an out-of-range
// double to int is undefined). Truncation plus a correction instead of std::floor, which
// is a library call on the baseline x86-64 target.
inline int texelIndexOf(double c) {
    constexpr double kLimit = 1073741824.0;
    const double saturated = c > -kLimit ? (c < kLimit ? c : kLimit) : -kLimit;
    const int truncated = int(saturated);
    return truncated - (saturated < double(truncated) ? 1 : 0);
}

}  // namespace shadowlab
