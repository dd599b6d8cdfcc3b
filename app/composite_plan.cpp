#include "app/composite_plan.h"

#include <algorithm>
#include <array>
#include <vector>

#include "app/plots/svg.h"
#include "scenes/bounds.h"

namespace shadowlab {
namespace {

using svg::format;

constexpr double kSize = 640, kMargin = 20;

struct PlanView {
    Aabb box;
    double scale;
    double x(const glm::dvec3& p) const { return kMargin + (p.x - box.min.x) * scale; }
    double y(const glm::dvec3& p) const { return kMargin + (p.z - box.min.z) * scale; }
};

PlanView fitView(const DifferentialModel& m, const std::vector<Aabb>& objectBoxes) {
    Aabb box = objectBoxes.front();
    for (const Aabb& b : objectBoxes) box = merged(box, b);
    for (const uint32_t p : m.transfers.receiverPatches) {
        for (const glm::dvec3& c : m.model.corners(p)) box.min = glm::min(box.min, c), box.max = glm::max(box.max, c);
    }
    const double extent = std::max({box.max.x - box.min.x, box.max.z - box.min.z, 1e-6});
    return {box, (kSize - 2 * kMargin) / extent};
}

std::string polygon(const PlanView& v, const std::array<glm::dvec3, 4>& c, const char* fill, const char* stroke) {
    std::string points;
    for (const glm::dvec3& p : c) points += format("%.1f,%.1f ", v.x(p), v.y(p));
    return format(R"(<polygon points="%s" fill="%s" stroke="%s" stroke-width="0.5"/>)" "\n", points.c_str(), fill,
                  stroke);
}

// Per source slot, the cluster holding it, or -1.
std::vector<int> clusterOfSource(const DifferentialModel& m, const CompositeFrame& frame) {
    std::vector<int> cluster(m.transfers.sources.size(), -1);
    for (size_t c = 0; c < frame.clusters.size(); ++c) {
        for (const uint32_t s : frame.clusters[c].patches) cluster[s] = int(c);
    }
    return cluster;
}

const char* colourOf(int cluster) {
    return cluster < 0 ? "#999" : svg::kPalette[size_t(cluster) % std::size(svg::kPalette)];
}

}  // namespace

std::string formatPlanSvg(const DifferentialModel& m, const CompositeFrame& frame,
                          const std::vector<Aabb>& objectBoxes) {
    const PlanView v = fitView(m, objectBoxes);
    std::string text = format(R"(<svg xmlns="http://www.w3.org/2000/svg" width="%.0f" height="%.0f" )"
                              R"(viewBox="0 0 %.0f %.0f" font-family="sans-serif" font-size="10">)" "\n",
                              kSize, kSize, kSize, kSize);
    text += format(R"(<defs><clipPath id="frame"><rect x="0" y="0" width="%.0f" height="%.0f"/></clipPath></defs>)"
                   "\n", kSize, kSize);
    text += format(R"svg(<rect width="%.0f" height="%.0f" fill="#fff"/><g clip-path="url(#frame)">)svg" "\n", kSize,
                   kSize);
    std::vector<uint8_t> listed(m.model.patches.size(), 0);
    for (const uint32_t slot : frame.hits.receiverPatches) listed[m.transfers.receiverPatches[slot]] = 1;
    for (const uint32_t p : m.transfers.receiverPatches) {
        text += polygon(v, m.model.corners(p), listed[p] ? "#cfe3f7" : "none", "#ccc");
    }
    const std::vector<int> cluster = clusterOfSource(m, frame);
    // A leaf shaft above the source tree's leaves stands for its pairs: a line from each.
    for (const int32_t index : frame.hits.leafShafts) {
        const ShaftNode& shaft = m.shafts.nodes[size_t(index)];
        const glm::dvec3 to = centre(m.receiverOctree.nodes[size_t(shaft.receiver)].bounds);
        forEachPatch(m.sourceTree, shaft.source, [&](uint32_t slot) {
            const glm::dvec3 from = m.model.centre(m.transfers.sources[slot]);
            text += format(R"(<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-opacity="0.25"/>)" "\n",
                           v.x(from), v.y(from), v.x(to), v.y(to), colourOf(cluster[slot]));
        });
    }
    for (size_t s = 0; s < m.transfers.sources.size(); ++s) {
        const bool inCluster = cluster[s] >= 0;
        text += polygon(v, m.model.corners(m.transfers.sources[s]), inCluster ? colourOf(cluster[s]) : "none",
                        inCluster ? "#333" : "#e69f00");
    }
    for (size_t c = 0; c < frame.lights.size(); ++c) {
        const glm::dvec3& l = frame.lights[c];
        text += format(R"(<circle cx="%.1f" cy="%.1f" r="5" fill="none" stroke="%s" stroke-width="2"/>)"
                       R"(<text x="%.1f" y="%.1f">%zu</text>)" "\n",
                       v.x(l), v.y(l), colourOf(int(c)), v.x(l) + 6, v.y(l) - 6, c);
    }
    for (const Aabb& b : objectBoxes) {
        text += polygon(v, {b.min, glm::dvec3(b.max.x, 0, b.min.z), b.max, glm::dvec3(b.min.x, 0, b.max.z)}, "none",
                        "#d00");
    }
    text += format(R"(</g><text x="%.0f" y="14">plan (x right, z down): %zu leaf shafts touched, )"
                   R"(%zu sources listed, %zu clusters</text>)" "\n",
                   kMargin, frame.hits.leafShafts.size(), frame.hits.sourcePatches.size(), frame.clusters.size());
    return text + "</svg>\n";
}

}  // namespace shadowlab
