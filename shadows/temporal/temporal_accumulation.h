// Temporal accumulation as a setting of a technique (docs/temporal.md): `temporal=on`
// averages the technique's V over the frames of a sequence, each frame's history reprojected
// by the motion vectors (reprojection.h) and blended (accumulation.h), as engines resolve
// a noisy shadow with TAA (Jimenez 2014, interleaved gradient noise rotating a PCF kernel
// that TAA accumulates). With `temporal=off`, the default, the technique is as it was, to
// the bit. A frame that stands alone, and a sequence's first, is the technique's own.
#pragma once

#include "shadows/settings_table.h"
#include "shadows/technique.h"
#include "shadows/temporal/accumulation.h"
#include "shadows/temporal/reprojection.h"

namespace shadowlab {

struct TemporalSettings {
    bool on = false;
    AccumulationSettings accumulation;
    ReprojectionSettings reprojection;
};
const SettingsTable<TemporalSettings>& temporalSettingsTable();

// `technique` with the settings `temporal`, `temporal-frames`, `temporal-clamp` and
// `temporal-gamma`. Its stats gain `history_rejected_pixels` (hit pixels whose history the
// reprojection rejected this frame) and `history_frames_mean_count`, its debug buffers the
// history, reprojected and clamped, and the frames each pixel holds. Temporal accumulation
// of tinted casters' coloured V is refused (not built).
Technique withTemporalAccumulation(Technique technique);

}  // namespace shadowlab
