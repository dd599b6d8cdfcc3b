// The largest scene shadowlab loads, checked before anything of that size is allocated, so
// a small file cannot ask for more memory than a 24 GB machine has (docs/scene-format.md,
// "Limits"). A scene at the limits needs a few GB: its world geometry, Embree's BVH for the
// reference (about 100 bytes per triangle) and one technique's buffers.
#pragma once

#include <cstddef>
#include <cstdint>

namespace shadowlab {

inline constexpr uint64_t kMaxSceneTriangles = uint64_t(1) << 25;   // world-space, after instancing
inline constexpr uint64_t kMaxSceneVertices = uint64_t(1) << 25;
// Voxels of all density volumes together: 64 MiB of float extinction.
inline constexpr uint64_t kMaxSceneVoxels = uint64_t(1) << 24;
inline constexpr uint64_t kMaxInstances = uint64_t(1) << 16;        // after "repeat"
inline constexpr uint64_t kMaxFileBytes = uint64_t(1) << 31;        // any scene, mesh or image file read
inline constexpr int kMaxJsonDepth = 64;                            // nesting of a scene file
// Lights of a scene: a frame keeps a visibility buffer per light (docs/many-lights.md).
inline constexpr size_t kMaxSceneLights = 16;
// Channels of an EXR read (compare): the most `render --aov` writes, its 15 fixed channels
// and a V per light.
inline constexpr size_t kMaxImageChannels = 16 + kMaxSceneLights;
inline constexpr size_t kMaxPathKeyframes = size_t(1) << 16;         // of a fly-through's camera path
inline constexpr int kMaxPathFrames = 100000;                        // frames a path is sampled at
// A path's CSV file: its most keyframes at 10 numbers of 100 characters, comments aside.
inline constexpr uint64_t kMaxPathFileBytes = uint64_t(kMaxPathKeyframes) * 1024;
// The largest magnitude of a world-space coordinate, in metres: of a camera's eye and
// target, a light's position, every vertex after instancing, a path's keys. Far inside
// what every stage handles (float products of two coordinates stay finite; Embree aborts
// near 2e18), and still 100 times our largest scene (hard/huge-depth-range, 1e4 m).
inline constexpr double kMaxCoordinate = 1e6;

}  // namespace shadowlab
