#include "shading/environment/environment_pyramid.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "raster/portable_constants.h"
#include "raster/portable_math.h"

namespace shadowlab {
namespace {

// Level `level` of a map: texel (i, j) spans the map's columns [i 2^level, (i + 1) 2^level) and
// rows [j 2^level, (j + 1) 2^level), clipped to the map. Fills everything but the radiance
// and the brightest luminance.
PyramidLevel levelGeometry(const EnvironmentMap& map, int level) {
    const int step = 1 << level;
    PyramidLevel out;
    out.width = (map.width + step - 1) / step, out.height = (map.height + step - 1) / step;
    const size_t texels = size_t(out.width) * size_t(out.height);
    out.x.resize(texels), out.y.resize(texels), out.z.resize(texels);
    out.solidAngle.resize(texels), out.cosExtent.resize(texels), out.sinExtent.resize(texels);
    out.radiance.resize(texels), out.brightest.resize(texels);
    tbb::parallel_for(0, out.height, [&](int j) {
        const int row0 = j * step, row1 = std::min(row0 + step, map.height);
        const double theta0 = map.rowEdgeTheta(row0), theta1 = map.rowEdgeTheta(row1);
        const double widest = portable::sin(std::clamp(0.5 * kPi, theta0, theta1));
        const double zone = portable::cos(theta0) - portable::cos(theta1);
        for (int i = 0; i < out.width; ++i) {
            const int column0 = i * step, column1 = std::min(column0 + step, map.width);
            const double phiWidth = map.columnEdgePhi(column1) - map.columnEdgePhi(column0);   // the rotation cancels
            const glm::dvec3 d = map.direction(0.5 * (column0 + column1) / map.width, 0.5 * (row0 + row1) / map.height);
            const size_t k = out.index(i, j);
            out.x[k] = d.x, out.y[k] = d.y, out.z[k] = d.z;
            out.solidAngle[k] = phiWidth * zone;
            const double extent = std::max(theta1 - theta0, phiWidth * widest);
            out.cosExtent[k] = portable::cos(extent), out.sinExtent[k] = portable::sin(extent);
        }
    });
    return out;
}

}  // namespace

EnvironmentPyramid buildPyramid(const EnvironmentMap& map) {
    EnvironmentPyramid pyramid;
    pyramid.levels.push_back(levelGeometry(map, 0));
    for (size_t k = 0; k < map.radiance.size(); ++k) {
        pyramid.levels[0].radiance[k] = glm::dvec3(map.radiance[k]);
        pyramid.levels[0].brightest[k] = luminance(glm::dvec3(map.radiance[k]));
    }
    while (pyramid.levels.back().width > 8 && pyramid.levels.back().height > 4) {
        const int level = int(pyramid.levels.size());
        PyramidLevel coarse = levelGeometry(map, level);
        const PyramidLevel& fine = pyramid.levels.back();
        tbb::parallel_for(0, coarse.height, [&](int j) {
            for (int i = 0; i < coarse.width; ++i) {
                glm::dvec3 sum(0.0);
                double solidAngle = 0.0, brightest = 0.0;
                for (int fj = 2 * j; fj < std::min(2 * j + 2, fine.height); ++fj) {
                    for (int fi = 2 * i; fi < std::min(2 * i + 2, fine.width); ++fi) {
                        const size_t k = fine.index(fi, fj);
                        sum += fine.radiance[k] * fine.solidAngle[k];
                        solidAngle += fine.solidAngle[k];
                        brightest = std::max(brightest, fine.brightest[k]);
                    }
                }
                coarse.radiance[coarse.index(i, j)] = sum / solidAngle;
                coarse.brightest[coarse.index(i, j)] = brightest;
            }
        });
        pyramid.levels.push_back(std::move(coarse));
    }
    return pyramid;
}

}  // namespace shadowlab
