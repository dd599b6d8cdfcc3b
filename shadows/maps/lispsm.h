// Light space perspective shadow maps (Wimmer, Scherzer and Purgathofer, EGSR 2004; Real-
// Time Rendering, 4th ed., section 7.4.1, Figures 7.15 and 7.17): a directional light's
// orthographic map warped by a perspective transform whose axis lies in the map's plane,
// along the view direction projected onto it, so that texels crowd towards the viewer.
// The light's rays stay parallel after the warp (they are perpendicular to the warp's
// axis), so the map remains an orthographic view of the warped space.
//
// The warp's projection centre sits at the eye's position across the axis, a distance n
// before the receivers along it; n is the paper's optimum for a perspective camera,
//     n_opt = (z_n + sqrt(z_n z_f)) / sin(gamma)                         (section 5)
// with z_n, z_f the nearest and farthest receiver depths in the camera and gamma the angle
// between the view and light directions. As gamma -> 0 (the light behind or in front of
// the viewer: "dueling frusta", RTR 7.4.1) n_opt grows without bound and the warp
// degenerates to the uniform map; below kMinSinGamma the uniform map is returned as is.
#pragma once

#include "scenes/scene.h"
#include "shading/gbuffer.h"
#include "shadows/light_view.h"

namespace shadowlab {

struct LispsmView {
    LightView view;
    double nOpt = 0.0;       // infinity when the uniform map was kept
    double sinGamma = 0.0;
};

// `uniform` is fitLightView()'s orthographic view for the directional `sun`; its depth
// range (near and far along the light) is kept. marginTexels as in LightFitOptions.
LispsmView lispsmView(const LightView& uniform, const Light& sun, const Camera& camera, const GBuffer& receivers,
                      int resolution, double marginTexels);

}  // namespace shadowlab
