// An environment map: radiance arriving from infinitely far away, as a function of direction,
// stored as a latitude-longitude image (docs/conventions.md, "Lights"). Texel (i, j) of a
// W x H map holds the radiance from the region
//
//     u in [i / W, (i + 1) / W],   v in [j / H, (j + 1) / H],
//     u = 0.5 + atan2(d.x, -d.z) / (2 pi),   v = acos(d.y) / pi,
//
// so row 0 is the zenith (+Y), the last row the nadir, u = 0.5 looks along -Z and u = 0.75
// along +X. In angles, phi = 2 pi (u - 0.5) and theta = pi v give the direction
// d = (sin theta sin phi, cos theta, -sin theta cos phi). The map is piecewise constant over
// these regions: every integral over the sphere here (solid angles, spherical harmonics,
// sampled lights, the reference) integrates that function, so the answers agree exactly
// with each other and a texel's solid angle is its exact area on the sphere,
//
//     dOmega_j = (2 pi / W) (cos theta_j - cos theta_{j+1}),   theta_j = pi j / H,
//
// which sums to 4 pi. A rotation turns the map about +Y by `rotationRadians`, right-handed
// (counter-clockwise seen from above, so -Z turns towards -X): the world direction of map
// direction d is R_y d, whose phi is the map's less the rotation.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shading/luminance.h"   // what the samplers and integrators weigh texels by

namespace shadowlab {

struct EnvironmentMap {
    int width = 0, height = 0;
    std::vector<glm::vec3> radiance;   // row-major, row 0 the zenith; linear, >= 0, finite
    double rotationRadians = 0.0;      // about +Y
    std::string source;                // the file it was read from, for messages

    glm::vec3 at(int i, int j) const { return radiance[size_t(j) * size_t(width) + size_t(i)]; }

    // Polar angle theta of the edge between rows j - 1 and j (j in [0, height]).
    double rowEdgeTheta(int j) const;
    // World azimuth phi of the edge between columns i - 1 and i (i in [0, width]), rotation
    // included: phi = 2 pi (i / W - 0.5) - rotation.
    double columnEdgePhi(int i) const;
    // The exact solid angle of any texel of row j.
    double texelSolidAngle(int j) const;

    // The world direction at map coordinates (u, v), rotation included.
    glm::dvec3 direction(double u, double v) const;
    // The map coordinates (u, v) of a world direction (any length but 0), u in [0, 1).
    glm::dvec2 coordinates(const glm::dvec3& direction) const;
    // The texel whose region holds the direction (a NaN direction, which no caller should
    // pass, gives texel (0, 0)).
    glm::ivec2 texelToward(const glm::dvec3& direction) const;
};


// The integral of the map's radiance over the sphere, sum of L dOmega over every texel.
glm::dvec3 environmentPower(const EnvironmentMap& map);

// A uniform map of one radiance (tests, furnace scenes).
EnvironmentMap constantEnvironment(int width, int height, const glm::vec3& radiance);

}  // namespace shadowlab
