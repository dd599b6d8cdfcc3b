// Soft shadows of a disk light from fins on silhouette edges (Cai, Jia, Wang, Hu and Martin
// 2006, "Rendering Soft Shadows using Multi-layered Shadow Fins"): the pipeline of `fins`
// and of the two older methods it compares itself with (its sections 2 and 7.1), which
// differ only in their fins (fins.cpp, smoothies.cpp, penumbra_maps.cpp):
//
//   technique       fins            edge weight  fin width                   layers
//   fins            inner + outer   0.5 (eq. 1)  light radius R (eq. 3)      param (16)
//   penumbra-maps   outer           1            light radius R (eq. 3)      1
//   smoothies       outer           1            angular width t_s (param)   1
//
// Outer-only methods put the whole penumbra outside the hard shadow, so they over-estimate
// the umbra; smoothies also ignore the light's size (Cai et al., section 7.1).
//
// Per frame:
//   1. the light's view from the disk's centre along its normal, fitted to the receivers
//      (light_view.h); its far plane is the reference receiver plane L_0 (section 3.1);
//   2. silhouette edges w.r.t. the centre (silhouette.h), for a cut-out the outline of its
//      texture's opaque texels instead of its own edges (cut_out_outline.h), fins
//      (fin_geometry.h);
//   3. layers of about equal numbers of edges (fin_layers.h, section 4.1), each object
//      with its fins in the layer of its edges' median midpoint;
//   4. per layer, near to far: the hard shadow map of the layer's objects, the inner and
//      outer penumbra maps of their fins (fin_maps.h), and the illuminance buffer
//      updated from them (illuminance_buffer.h, sections 3.4 and 4.2).
// V is the illuminance buffer; the final image multiplies it into the shading (section 4.3).
#pragma once

#include <string>
#include <vector>

#include "shadows/fins/fin_geometry.h"
#include "shadows/fins/illuminance_buffer.h"
#include "shadows/settings_table.h"
#include "shadows/technique.h"

namespace shadowlab {

// `resolution` and `falloff`, which every fin technique has: rows each one's table includes.
struct FinMapSettings {
    int resolution = 1024;   // texels per side of the hard shadow and penumbra maps
    Falloff falloff = Falloff::Linear;
};

const SettingsTable<FinMapSettings>& finMapSettingsTable();

struct FinSettings {
    std::string technique;
    LightPlane light;
    FinStyle style;
    int layers = 1;
    FinMapSettings maps;
};

// The disk light and the maps' settings; the technique adds its style and layers. Throws
// std::invalid_argument unless the light is a disk.
FinSettings finSettings(const ShadowInputs& in, const std::string& technique, const FinMapSettings& maps);

ShadowOutputs renderFinShadows(const ShadowInputs& in, const FinSettings& settings);

}  // namespace shadowlab
