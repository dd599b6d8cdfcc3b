// Layering the light's space for multi-layered shadow fins (Cai et al. 2006, section 4.1):
// slabs between planes parallel to the light's plane, each holding about the same number
// of silhouette edges, so that fins of one layer rarely overlap.
//
// The depth range [zNear, zFar] of the light's view (distances L from the light's plane) is
// cut into equally spaced sub-layers (1024, as in the paper). The silhouette edges are
// counted per sub-layer by their midpoints, and consecutive sub-layers are merged into k
// layers: a layer closes after the sub-layer at which the running count reaches its share,
// j * total / k for the j-th layer. Layers thus start and end on sub-layer boundaries, and a
// distance belongs to the layer of its sub-layer. The last layer reaches zFar. Fewer than k
// layers result when edges crowd into a few sub-layers (a sub-layer is never split).
//
// What goes into a layer. Section 4.1 puts each fin in the layer of its edge's midpoint, and
// section 5 clips the scene's triangles at the layer planes. Done that way here, an object
// that a layer plane cuts leaves a piece in a layer without its silhouette: the piece's hard
// shadow has no fins, and the minimum of section 4.2 turns the inner penumbra that the
// object's fins make into umbra (docs/shadow-fins.md has the figures: the sphere's whole
// inner penumbra goes dark). So each instance goes whole, with all its fins, into one
// layer: the layer of the median midpoint of its silhouette edges. Objects at different
// depths still get different layers, which is what the multi-layer algorithm is for
// (Figure 2: several objects along one beam of light).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace shadowlab {

inline constexpr int kFinSubLayers = 1024;   // section 4.1: "for example 1024 of them"

class LightLayers {
public:
    // Throws std::invalid_argument unless 0 < zNear < zFar, layers >= 1 and subLayers >= 1.
    LightLayers(std::span<const double> edgeDistance, double zNear, double zFar, int layers,
                int subLayers = kFinSubLayers);

    int count() const { return int(firstSubLayer_.size()) - 1; }
    int subLayerOf(double L) const;           // clamped to [0, subLayers)
    int layerOf(double L) const;

private:
    double zNear_, zFar_;
    int subLayers_;
    std::vector<int> firstSubLayer_;   // per layer, then subLayers_ at the end
    std::vector<int> layerOfSubLayer_;
};

// The layer of each instance: that of the median of edgeDistance over its edges
// (edgeInstance: per edge, its instance), or of fallbackDistance[i] if it has none.
std::vector<int> instanceLayers(const LightLayers& layers, std::span<const double> edgeDistance,
                                std::span<const uint32_t> edgeInstance, std::span<const double> fallbackDistance);

}  // namespace shadowlab
