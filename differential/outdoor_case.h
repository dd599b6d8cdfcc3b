// The outdoor compositing case: a panorama stands for the real world. The
// photograph is the panorama seen through a pinhole camera at its centre; the local model
// is a ground plane under the camera, whose reflectance is estimated from the panorama (the
// mean radiance of the ground below, times pi, over the irradiance of the sky above, as
// Debevec 1998 fits a local scene to its probe); the sources are the map's upper half cut
// into blocks of texels, each a distant patch on a dome (environment_dome.h).
#pragma once

#include "differential/scene/compositing_scene.h"
#include "shading/environment/environment_map.h"

namespace shadowlab {

struct OutdoorSettings {
    int width = 640, height = 400;
    int domeColumns = 32, domeRows = 8;   // blocks of the upper hemisphere
    double domeRadiusM = 200.0;
    double cameraHeightM = 1.6;
};

// The object walks 2 m across the path in front of the camera in 11 frames (a 10-unit
// mesh such as the bunny, scaled by 0.06). Throws std::invalid_argument for a size outside
// 16..4096 pixels per side, a dome environmentDome refuses, or a map with no light above
// the horizon.
CompositingScene compositingOutdoor(const EnvironmentMap& map, const Mesh& object,
                                    const OutdoorSettings& settings = {});

}  // namespace shadowlab
