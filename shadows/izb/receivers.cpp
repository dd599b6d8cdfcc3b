// Irregular z-buffer, stage 1: the camera samples that can receive light become the
// origins of shadow segments, exactly as the reference's shadow rays (reference.cpp), so
// the two answer the same question per pixel.
#include <algorithm>
#include <cmath>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "shading/lights.h"
#include "shadows/izb/izb.h"
#include "shadows/ray_offset.h"

namespace shadowlab::izb {
namespace {

constexpr size_t kPixelsPerTask = 4096;   // pixels per task

// A chunk's lit points and their segments, as the segments kernel reads and writes them.
struct SegmentBatch {
    std::vector<double> column[10];   // P x y z, N x y z; origin x y z, tFar
    std::vector<uint32_t> pixel;

    SegmentBatch() {
        for (std::vector<double>& c : column) c.resize(kPixelsPerTask + kKernelPadding);
        pixel.resize(kPixelsPerTask);
    }
    void add(uint32_t k, const glm::vec3& P, const glm::vec3& N, size_t n) {
        column[0][n] = P.x, column[1][n] = P.y, column[2][n] = P.z;
        column[3][n] = N.x, column[4][n] = N.y, column[5][n] = N.z;
        pixel[n] = k;
    }
    PointColumns points() const {
        return {column[0].data(), column[1].data(), column[2].data(), column[3].data(), column[4].data(), column[5].data()};
    }
    SegmentColumns segments() { return {column[6].data(), column[7].data(), column[8].data(), column[9].data()}; }
    double tFar(size_t n) const { return column[9][n]; }
    Receiver receiver(size_t n) const {
        return {glm::vec3(float(column[6][n]), float(column[7][n]), float(column[8][n])), pixel[n], tFar(n)};
    }
};

}  // namespace

Receivers gatherReceivers(const GBuffer& g, const Light& light, double diagonal, std::vector<float>& visibility,
                          raster::SimdLevel simd) {
    const HomogeneousLight h = homogeneousLight(light);
    const LightReach reaches(light);
    const SegmentConstants constants{{h.x, h.y, h.z, h.w}, diagonal, kShadowRayOffsetPerScale};
    const SegmentKernel computeSegments = kernels(simd).segments;
    // Chunks of pixels in parallel: each decides its own pixels (writing only their bytes),
    // computes the lit ones' segments a vector at a time and keeps, in pixel order, those
    // with a segment left (a point light nearer than the offset leaves none: seen, as in the
    // reference). The chunks are then joined in order, each copied to the slot an exclusive
    // prefix sum of their sizes gives it.
    const size_t chunks = (g.pixelCount() + kPixelsPerTask - 1) / kPixelsPerTask;
    visibility.assign(g.pixelCount(), 0.0f);
    std::vector<Receivers> kept(chunks);
    tbb::enumerable_thread_specific<SegmentBatch> batches;   // one per worker, reused by its chunks
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
        SegmentBatch& batch = batches.local();
        size_t lit = 0;
        for (size_t k = c * kPixelsPerTask; k < std::min(g.pixelCount(), (c + 1) * kPixelsPerTask); ++k) {
            if (!g.hit[k] || !reaches(g.position[k], g.normal[k])) continue;
            visibility[k] = 1.0f;
            batch.add(uint32_t(k), g.position[k], g.normal[k], lit++);
        }
        computeSegments(constants, batch.points(), uint32_t(lit), batch.segments());
        kept[c].reserve(lit);
        for (size_t n = 0; n < lit; ++n) {
            if (batch.tFar(n) > 0.0) kept[c].push_back(batch.receiver(n));
        }
    });
    std::vector<size_t> first(chunks + 1, 0);
    for (size_t c = 0; c < chunks; ++c) first[c + 1] = first[c] + kept[c].size();
    Receivers receivers(first[chunks]);
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) { std::copy(kept[c].begin(), kept[c].end(), receivers.begin() + first[c]); });
    return receivers;
}

}  // namespace shadowlab::izb
