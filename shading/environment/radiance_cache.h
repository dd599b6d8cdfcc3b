// The radiance cache (DeCoro and Rusinkiewicz 2008, section 3.1, after Miller and Hoffman
// 1984): under distant light and a distant viewer, the light a surface of a given material
// reflects towards the viewer depends on its normal alone,
//
//     C(N) = integral over the sphere of f(l, v; N) L(l) max(0, N . l) dl,
//
// so C is tabulated once per frame and material over the sphere of normals (with the
// material's one albedo: a textured material, whose albedo varies over the surface, has no
// table; shadows/environment/unshadowed_light.h refuses it), for any BRDF
// shading/shade.h's brdf() evaluates (Blinn-Phong, which prefiltered maps cannot serve,
// included), and looked up per pixel. v is one direction for the whole frame (the camera's
// axis, towards the eye): the distant-viewer approximation, exact for an orthographic view,
// off towards the image's edges by the angle between a pixel's ray and the axis.
//
// The table is an octahedral map of normals (Praun and Hoppe 2003; the encoding of Cigolle et
// al., JCGT 3(2), 2014), size x size texels (the paper's 128^2), each the integral at its
// centre's normal, read bilinearly (clamped at the square's border). Each integral is a sum
// over a tiling of the sphere by texels of the map's pyramid (environment_pyramid.h), each
// weighted by f cos at its centre times its solid angle, a texel split into its children
// while the weight's spread across it (its corners against its centre, in luminance) times
// its solid angle and brightness (its brightest map texel, at least the map's mean) exceeds
// 10^-3 of the weight's integral times the map's mean luminance, as prefiltered_lobe.h does for
// symmetric lobes. Rows in parallel, one task each: the same bits for any thread count.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"
#include "shading/environment/environment_map.h"
#include "shading/environment/environment_pyramid.h"

namespace shadowlab {

struct RadianceCache {
    int size = 0;
    std::vector<glm::vec3> radiance;   // row-major, octahedral
};

// Throws std::invalid_argument for a size outside 2..1024.
RadianceCache buildRadianceCache(const EnvironmentMap& map, const EnvironmentPyramid& pyramid, const Material& material,
                                 const glm::dvec3& toViewer, int size = 128);

glm::dvec3 lookupRadianceCache(const RadianceCache& cache, const glm::dvec3& N);

// The octahedral encoding: a unit vector to [0, 1]^2, and back.
glm::dvec2 octahedralEncode(const glm::dvec3& n);
glm::dvec3 octahedralDecode(const glm::dvec2& uv);

}  // namespace shadowlab
