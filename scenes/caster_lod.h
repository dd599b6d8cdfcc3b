// Shadow level of detail by geometry: the casters' meshes simplified to a share of their
// triangles while the receivers, what the camera sees, stay whole. Subtractive shadows
// (DeCoro and Rusinkiewicz 2008, section 1) trade shadow fidelity for speed by the number
// of shadow-casting lights and the resolution of the shadow buffer, "inspired by existing
// work on geometric simplification"; this is the third knob, the simplification itself,
// for every technique (the frame's `caster-lod` parameter, frame/render.h).
//
// Each mesh is simplified once, whatever its instances, by meshoptimizer's edge-collapse
// simplifier (quadric error) on its positions welded by value, so that seams of split
// vertices do not hold the simplifier back. Open borders are locked: an open surface (a
// ground quad, a wall) keeps its outline, and a two-triangle plane stays what it was. The
// result is deterministic: the same mesh and ratio give the same triangles on any machine
// with the same meshoptimizer.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "scenes/prepared_scene.h"
#include "scenes/scene.h"

namespace shadowlab {

// The simplified copy of a scene, and what the simplification did.
struct SimplifiedScene {
    Scene scene;
    // The simplifier's own estimate of each instance's largest deviation, in world metres:
    // meshoptimizer's relative error times the mesh's extent times the instance's largest
    // scale; 0 for an instance whose mesh was not simplified (or lost no shape, a flat grid).
    std::vector<float> instanceErrorM;
    double errorM() const;   // the largest of them; 0 with no instance
};

// The scene with every mesh simplified towards `ratio` of its triangles, in (0, 1], but
// never below 4 (a closed mesh stays a solid, a tetrahedron at the least, and no mesh
// vanishes); a mesh may keep more where locked borders or its topology stop the
// simplifier, and one already at its target is kept as it is. A simplified mesh's shading
// normals are dropped (casters are not shaded). Throws
// std::invalid_argument for a ratio outside (0, 1].
SimplifiedScene simplifyMeshes(const Scene& scene, double ratio);

// The casters of `prepared` at a ratio: at 1, `prepared` itself; below, its simplified copy,
// built on the first call for that ratio and kept with the prepared scene
// (PreparedScene::derived), one per ratio asked for. Only the copy's geometry (meshes,
// instances, world, edge adjacency) is meant to be read: its camera and lights are those
// `prepared` had when it was built. `builtMs` gets the wall time of the simplification to
// the one call that made it, nothing otherwise. Thread-safe.
struct CasterLevel {
    const PreparedScene& casters;
    std::span<const float> instanceErrorM;   // SimplifiedScene::instanceErrorM; empty at ratio 1
    double errorM() const;                   // the largest of them; 0 at ratio 1
};
CasterLevel casterLevel(const PreparedScene& prepared, double ratio, std::optional<double>* builtMs = nullptr);

}  // namespace shadowlab
