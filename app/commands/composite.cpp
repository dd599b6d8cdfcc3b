// `shadowlab composite`: the options of differential rendering into a photograph; its run
// is app/composite.h.

#include <CLI/CLI.hpp>

#include "app/commands/commands.h"
#include "app/composite.h"
#include "raster/thread_count.h"
#include "shadows/depth_map.h"

namespace shadowlab {

void addCompositeCommand(CLI::App& command) {
    CompositeArgs& a = argumentsRunBy<CompositeArgs>(command, runCompositeCommand);
    CLI::App* c = command.description("a synthetic object's shadows composited into a photograph (Gibson et al. 2003) and the exact differential reference");
    c->add_option("case", a.scene, "room (slid under the desk), room-lift (raised off the floor), outdoor (the forest panorama) chessboard (a real photograph), or a compositing scene file (.json, docs/scene-format.md); --width and --height apply to the room and outdoor cases")->capture_default_str();
    c->add_option("--passes", a.passes, "shadow passes n per frame; 0: one per occluded source")->delimiter(',')->capture_default_str()->check(CLI::Range(0, 100000));
    c->add_option("--frames", a.frames, "frames of the path (default: all)")->delimiter(',');
    c->add_option("--width", a.width, "image width")->capture_default_str()->check(CLI::Range(16, 4096));
    c->add_option("--height", a.height, "image height")->capture_default_str()->check(CLI::Range(16, 4096));
    c->add_option("--resolution", a.resolution, "texels per side of each cluster's shadow map")->capture_default_str()->check(CLI::Range(kMinMapResolution, kMaxMapResolution));
    c->add_option("--shadow-triangles", a.shadowTriangles, "triangles of the object the maps draw")->capture_default_str()->check(CLI::Range(4, 1 << 24));
    c->add_option("--source-share", a.sourceShare, "share of the radiant power the source set holds")->capture_default_str()->check(CLI::Range(1e-6, 1.0));
    c->add_option("--significance", a.significance, "the shaft hierarchy leaves out less than this share of any vertex's light (the paper's 2% rule)")->capture_default_str()->check(CLI::Range(1e-6, 1.0));
    c->add_option("--reference-strata", a.referenceStrata, "the reference's strata per side of an emitting and of a reflecting patch")->delimiter(',')->expected(2)->capture_default_str()->check(CLI::Range(1, 64));
    c->add_flag("--reference-convergence", a.referenceConvergence, "also render the reference at twice the strata per side and report the RMS between the two");
    c->add_flag("--ldr", a.ldr, "composite the 8-bit photograph with intensity transfers");
    c->add_flag("!--no-reference", a.reference, "skip the exact reference");
    c->add_flag("--masks", a.masks, "write each cluster's mask");
    c->add_flag("--ldr-error", a.ldrError, "also run Figure 3's experiment: the 8-bit path's error against the sources occluded");
    c->add_option("--runs", a.runs, "timed runs per frame (median)")->capture_default_str()->check(CLI::Range(1, 1000));
    c->add_option("--warmup", a.warmupRuns, "untimed runs first")->capture_default_str()->check(CLI::Range(0, 1000));
    c->add_option("--threads", a.threads, "worker threads (0: all cores)")->capture_default_str()->check(CLI::Range(0, kMaxThreads));
    c->add_option("--out", a.outDir, "directory for the images and composite.json")->capture_default_str();
}

}  // namespace shadowlab
