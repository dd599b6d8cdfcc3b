#include "shadows/filtered/soft_shadow_map.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "shading/light_sampling.h"
#include "shading/lights.h"
#include "shadows/kept_raster.h"
#include "shadows/light_view.h"

namespace shadowlab {
namespace {

constexpr double kFarPlaneHeadroom = 1.25;   // far plane / farthest receiver's distance

// Half the light's extent (m) along the unit direction e: the support function of the
// disk (an ellipse once projected) or of the rectangle.
double halfExtentAlong(const AreaLightFrame& light, const glm::dvec3& e) {
    const double a = glm::dot(light.axisA, e), b = glm::dot(light.axisB, e);
    return light.disk ? std::sqrt(a * a + b * b) : std::abs(a) + std::abs(b);
}

// w_light in texels at unit distance for a map of `view` (texels per unit of x / (-z) and
// y / (-z): the projection's scale times half the map).
glm::dvec2 lightTexelsOf(const AreaLightFrame& frame, const LightView& view, int resolution) {
    const glm::dmat4 worldFromView = glm::inverse(view.viewFromWorld);
    const glm::dvec3 mapX = glm::normalize(glm::dvec3(worldFromView[0])), mapY = glm::normalize(glm::dvec3(worldFromView[1]));
    return glm::dvec2(2.0 * halfExtentAlong(frame, mapX) * view.clipFromView[0][0],
                      2.0 * halfExtentAlong(frame, mapY) * view.clipFromView[1][1]) *
           (0.5 * resolution);
}

// The far plane moved to distance zFar: only the depth row of an OpenGL projection
// depends on it (z_clip = -(f + n)/(f - n) z - 2 f n / (f - n)).
LightView withFarPlane(LightView view, double zFar) {
    const double n = view.zNear;
    view.zFar = zFar;
    view.clipFromView[2][2] = -(zFar + n) / (zFar - n);
    view.clipFromView[3][2] = -2.0 * zFar * n / (zFar - n);
    return view;
}

// Component `row` of m * (P, 1), with glm's operator*'s products and sums in its order,
// (m0 x + m1 y) + (m2 z + m3 1), so the bits are those of the full product.
double rowTimesPoint(const glm::dmat4& m, int row, const glm::dvec3& P) {
    return (m[0][row] * P.x + m[1][row] * P.y) + (m[2][row] * P.z + m[3][row]);
}

}  // namespace

double SoftShadowMap::distanceOf(float windowDepth) const {
    // OpenGL window depth of a perspective view, w = f (d - n) / ((f - n) d), inverted.
    const double n = zNear(), f = zFar();
    return f * n / (f - double(windowDepth) * (f - n));
}

void requireAreaLight(const Light& light, const std::string& technique) {
    if (light.type != LightType::Disk && light.type != LightType::Rectangle)
        throw std::invalid_argument(technique + ": needs an area light (disk or rectangle)");
}

namespace {

// The rasterizer that draws the map, kept with it (kept_raster.h).
struct SoftMapRasterizer {
    KeptRasterizer kept;
};

}  // namespace

const SoftShadowMap& renderSoftShadowMap(const ShadowInputs& in, int resolution, const raster::PolygonOffset& offset,
                                         double marginTexels, bool coverBlockerSearch) {
    const AreaLightFrame frame = areaLightFrame(in.light);
    const Light centre = pointLightFor(in.light);
    LightFitOptions fit;
    fit.resolution = resolution;
    fit.simd = in.simd;
    fit.marginTexels = marginTexels;
    fit.scratch = &in.kept().state<LightViewScratch>();
    LightView view = fitLightView(centre, in.gbuffer, in.casterWorld(), fit);
    if (coverBlockerSearch) {
        // The search region (eq. 7.6 at d_o = near) is widest for the farthest receiver and
        // never wider than 0.5 w_light / near texels from it: refit with that margin, so no
        // tap of a receiver at the border falls off the map (a widened map only shrinks it).
        const glm::dvec2 reach = 0.5 * lightTexelsOf(frame, view, resolution) / view.zNear;
        fit.marginTexels += std::ceil(std::max(reach.x, reach.y));
        view = fitLightView(centre, in.gbuffer, in.casterWorld(), fit);
    }
    // The fit puts the far plane just behind the farthest receiver, so the surface beyond
    // it would be clipped to "nothing" (z = 1) within a filter's reach, and the filtered
    // mean there would fall below the receiver's depth (false shadow). A quarter more
    // depth keeps the surface's own ramp under every filter (hundreds of texels even at a
    // grazing light) for a quarter of the depth resolution.
    view = withFarPlane(view, view.zFar * kFarPlaneHeadroom);
    SoftShadowMap& soft = in.kept().state<SoftShadowMap>();
    soft.map = renderDepthMap(in.casters(), view, {resolution, DepthLayer::First, offset, {}}, in.simd, std::move(soft.map),
                              &in.kept().state<SoftMapRasterizer>().kept.at(in.simd));
    soft.map.image(soft.linear);
    tbb::parallel_for(size_t(0), soft.linear.size(), [&](size_t k) {
        float& z = soft.linear[k];
        z = z >= 1.0f ? 1.0f : float(soft.normalised(soft.distanceOf(z)));
    });
    soft.light = in.light;
    soft.lightCentre = frame.centre;
    soft.lightTexels = lightTexelsOf(frame, view, resolution);
    return soft;
}

SoftReceiver softReceiver(const SoftShadowMap& soft, const glm::dvec3& P) {
    const glm::dmat4 &t = soft.map.texelFromWorld, &v = soft.map.view.viewFromWorld;
    // Only the rows used: texel x, y and w, and view z (-d_r).
    const double x = rowTimesPoint(t, 0, P), y = rowTimesPoint(t, 1, P), w = rowTimesPoint(t, 3, P);
    return {glm::dvec2(x / w, y / w), -rowTimesPoint(v, 2, P)};
}

glm::dvec2 sampleWidthTexels(const SoftShadowMap& soft, double dr, double dOccluder) {
    return soft.lightTexels * ((dr - dOccluder) / (dr * dOccluder));
}

TexelRect coneTexels(const SoftShadowMap& soft, const glm::dvec2& texel, double dr, double dOccluder) {
    const glm::dvec2 radius = 0.5 * sampleWidthTexels(soft, dr, dOccluder);
    const int last = soft.map.size - 1;
    const auto clamped = [&](double c) { return std::clamp(texelIndexOf(c), 0, last); };
    return {clamped(texel.x - radius.x), clamped(texel.y - radius.y), clamped(texel.x + radius.x),
            clamped(texel.y + radius.y)};
}

}  // namespace shadowlab
