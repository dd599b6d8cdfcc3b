// Backprojection's cull: where in the shadow map a patch can hide any of the light from a
// receiver. The points that project from P onto the light's square (a, b) in [-1, 1]^2,
// lying between P and the light, fill the pyramid with apex P and the square as its base
// (Guennebaud et al. 2006, section 3.2: the patches are projected from the receiver onto
// the light). Its section at view distance w from the light's centre is a quadrilateral
// whose corners, in texels, are C_i / w + k_i along its four edges (the map's projection
// divides by w, and along an edge the numerator is affine in w). A patch whose texels at
// its depths lie outside that section's bounding box projects off the square and sets no
// sample (whose centres lie half a cell inside it), so it need not be projected at all:
// most of a wide search region (two-heights: the rail's texels beside a ground receiver)
// lies there. The same samples are set either way.
#pragma once

#include <algorithm>
#include <array>

#include <glm/glm.hpp>

#include "shading/light_sampling.h"
#include "shadows/filtered/soft_shadow_map.h"

namespace shadowlab {

class LightPyramid {
public:
    LightPyramid(const SoftShadowMap& soft, const glm::dvec3& P, const AreaLightFrame& light) : soft_(soft) {
        const glm::dvec4 p = soft.map.texelFromWorld * glm::dvec4(P, 1.0);
        apexW_ = p.w;
        for (int i = 0; i < 4; ++i) {
            const glm::dvec3 corner = light.centre + (i & 1 ? 1.0 : -1.0) * light.axisA + (i & 2 ? 1.0 : -1.0) * light.axisB;
            const glm::dvec4 l = soft.map.texelFromWorld * glm::dvec4(corner, 1.0);
            const double dw = l.w - p.w;
            valid_ = valid_ && dw < 0.0;   // the light nearer the map's eye than P, as ever in practice
            k_[i] = glm::dvec2(l.x - p.x, l.y - p.y) / dw;
            c_[i] = glm::dvec2(p.x, p.y) - p.w * k_[i];
        }
    }

    // Whether nothing in texels [x0, x1] x [y0, y1] (texel corners) between window depths
    // near and far can project onto the light's square from P.
    bool misses(double x0, double y0, double x1, double y1, float near, float far) const {
        if (!valid_) return false;
        const double w0 = soft_.distanceOf(near), w1 = std::min(soft_.distanceOf(far), apexW_);
        if (!(w0 > 0.0) || !(w0 <= w1)) return false;
        // Each corner of the section moves monotonically with w: the box of both ends' holds all.
        glm::dvec2 lo(1e300), hi(-1e300);
        for (int i = 0; i < 4; ++i) {
            const glm::dvec2 t0 = c_[i] / w0 + k_[i], t1 = w1 == w0 ? t0 : c_[i] / w1 + k_[i];
            lo = glm::min(lo, glm::min(t0, t1)), hi = glm::max(hi, glm::max(t0, t1));
        }
        constexpr double kMargin = 0.5;   // texels: far beyond any rounding of w or of the corners
        return x1 < lo.x - kMargin || x0 > hi.x + kMargin || y1 < lo.y - kMargin || y0 > hi.y + kMargin;
    }

private:
    const SoftShadowMap& soft_;
    double apexW_ = 0.0;
    bool valid_ = true;
    std::array<glm::dvec2, 4> c_{}, k_{};
};

}  // namespace shadowlab
