// Triangle setup (see setup.h).
//
// Edge functions. For the edge from a to b, E(p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x)
// in sub-pixel units (window y grows downwards). It is positive inside a triangle whose
// determinant is positive; for the other orientation all three are negated, so the interior
// is always E >= 0, written A*x + B*y + C. Two triangles sharing an edge get exactly
// opposite (A, B, C), because the arithmetic is exact.
//
// Top-left rule (as Direct3D defines it in window coordinates with y down): a pixel centre
// exactly on an edge belongs to the triangle only if that edge is a left edge (the interior
// lies to its right, A > 0) or a top edge (horizontal with the interior below, A == 0 and
// B > 0). Of two triangles sharing an edge exactly one sees it as top-left, so a closed mesh
// covers every pixel centre exactly once. Non-top-left edges get a bias of -1.
//
// Reduction to pixel units. At pixel centre (i, j) = (256 i + 128, 256 j + 128) sub-pixels:
//   E = 256 (A i + B j) + K,  K = 128 A + 128 B + C - bias,
// and since A i + B j is an integer, E >= 0  <=>  A i + B j + floor(K / 256) >= 0.
// The kernels evaluate e = A i + B j + c with c = floor(K / 256): exact, and in pixel steps.
//
// Conservative mode (outer): the triangle touches the pixel square iff, for every edge, the
// square's corner furthest inside has E >= 0, and the bounding boxes overlap (the separating
// axis theorem in 2-D: the axes are the three edge normals and x and y). The furthest corner
// adds 128 (|A| + |B|); 129 instead of 128 also covers the half sub-pixel that snapping may
// have moved each vertex, so no pixel the unsnapped triangle touches is missed.
#include "raster/setup.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace shadowlab::raster {
namespace {

int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
int64_t ceilDiv(int64_t a, int64_t b) { return -floorDiv(-a, b); }

struct WindowVertex {
    int32_t x, y;        // snapped, sub-pixel units
    double z;            // window depth
    double inverseW;
    const float* varyings;
};

WindowVertex toWindow(const ClipVertex& v, int width, int height) {
    const double inverseW = 1.0 / double(v.position.w);
    const double x = (double(v.position.x) * inverseW + 1.0) * 0.5 * width;
    const double y = (1.0 - double(v.position.y) * inverseW) * 0.5 * height;   // row 0 at the top
    const double z = (double(v.position.z) * inverseW + 1.0) * 0.5;
    return {int32_t(std::nearbyint(x * kSubpixelOne)), int32_t(std::nearbyint(y * kSubpixelOne)), z, inverseW,
            v.varyings};
}

// Rotate so the vertex with the smallest (y, x) comes first: the planes are then computed
// from the same base vertex however the triangle was submitted (llvmpipe warns that the
// same primitive rotated otherwise gives different z).
void canonicalRotation(WindowVertex v[3]) {
    int first = 0;
    for (int k = 1; k < 3; ++k) {
        if (v[k].y < v[first].y || (v[k].y == v[first].y && v[k].x < v[first].x)) first = k;
    }
    const WindowVertex r[3] = {v[first], v[(first + 1) % 3], v[(first + 2) % 3]};
    for (int k = 0; k < 3; ++k) v[k] = r[k];
}

struct PixelBounds {
    int32_t minX, minY, maxX, maxY;
};

PixelBounds pixelBounds(const WindowVertex v[3], bool conservative, int width, int height) {
    int64_t lo[2] = {v[0].x, v[0].y}, hi[2] = {v[0].x, v[0].y};
    for (int k = 1; k < 3; ++k) {
        lo[0] = std::min<int64_t>(lo[0], v[k].x), hi[0] = std::max<int64_t>(hi[0], v[k].x);
        lo[1] = std::min<int64_t>(lo[1], v[k].y), hi[1] = std::max<int64_t>(hi[1], v[k].y);
    }
    int64_t first[2], end[2];
    for (int axis = 0; axis < 2; ++axis) {
        if (conservative) {
            // Pixel i touches [lo - 1, hi + 1] iff 256 i <= hi + 1 and 256 (i + 1) >= lo - 1.
            first[axis] = ceilDiv(lo[axis] - 1, kSubpixelOne) - 1;
            end[axis] = floorDiv(hi[axis] + 1, kSubpixelOne) + 1;
        } else {
            // Pixel centres 256 i + 128 inside [lo, hi].
            first[axis] = ceilDiv(lo[axis] - kSubpixelHalf, kSubpixelOne);
            end[axis] = floorDiv(hi[axis] - kSubpixelHalf, kSubpixelOne) + 1;
        }
    }
    return {int32_t(std::max<int64_t>(first[0], 0)), int32_t(std::max<int64_t>(first[1], 0)),
            int32_t(std::min<int64_t>(end[0], width)), int32_t(std::min<int64_t>(end[1], height))};
}

void setupEdges(const WindowVertex v[3], int64_t sign, bool conservative, TriangleSetup& out) {
    for (int k = 0; k < 3; ++k) {
        const WindowVertex& a = v[k];
        const WindowVertex& b = v[(k + 1) % 3];
        const int64_t A = -sign * (int64_t(b.y) - a.y);
        const int64_t B = sign * (int64_t(b.x) - a.x);
        const int64_t C = -(A * a.x + B * a.y);
        const bool topLeft = A > 0 || (A == 0 && B > 0);
        const int64_t K = conservative ? kSubpixelHalf * (A + B) + C + (kSubpixelHalf + 1) * (std::abs(A) + std::abs(B))
                                       : kSubpixelHalf * (A + B) + C - (topLeft ? 0 : 1);
        out.edgeA[k] = int32_t(A);
        out.edgeB[k] = int32_t(B);
        out.edgeC[k] = floorDiv(K, kSubpixelOne);
    }
}

// The affine function of window (x, y) taking values q[k] at the three vertices, evaluated
// in double and handed to the kernels as float at the centre of the reference pixel.
Plane planeThrough(const WindowVertex v[3], const double q[3], int32_t refX, int32_t refY, double offset = 0.0) {
    const double x0 = v[0].x / double(kSubpixelOne), y0 = v[0].y / double(kSubpixelOne);
    const double x1 = v[1].x / double(kSubpixelOne) - x0, y1 = v[1].y / double(kSubpixelOne) - y0;
    const double x2 = v[2].x / double(kSubpixelOne) - x0, y2 = v[2].y / double(kSubpixelOne) - y0;
    const double det = x1 * y2 - x2 * y1;
    const double perX = ((q[1] - q[0]) * y2 - (q[2] - q[0]) * y1) / det;
    const double perY = ((q[2] - q[0]) * x1 - (q[1] - q[0]) * x2) / det;
    const double atRef = q[0] + perX * (refX + 0.5 - x0) + perY * (refY + 0.5 - y0) + offset;
    return {float(atRef), float(perX), float(perY)};
}

// OpenGL 4.6 section 14.6.5: factor * max slope + units * r, where for a float depth
// buffer r = 2^(e - 23) and e is the exponent of the triangle's largest depth.
double polygonOffset(const PolygonOffset& offset, const WindowVertex v[3], const Plane& depth) {
    if (offset.factor == 0.0f && offset.units == 0.0f) return 0.0;
    const double maxSlope = std::max(std::abs(double(depth.perX)), std::abs(double(depth.perY)));
    const double maxZ = std::max({std::abs(v[0].z), std::abs(v[1].z), std::abs(v[2].z)});
    int exponent = 0;
    std::frexp(maxZ, &exponent);   // maxZ = m 2^exponent, m in [0.5, 1): IEEE exponent is exponent - 1
    const double r = std::ldexp(1.0, exponent - 1 - 23);
    return offset.factor * maxSlope + offset.units * r;
}

void setupPlanes(const WindowVertex v[3], const SetupContext& context, TriangleSetup& out,
                 std::vector<Plane>& planes) {
    const double z[3] = {v[0].z, v[1].z, v[2].z};
    out.depth = planeThrough(v, z, out.minX, out.minY);
    const double offset = polygonOffset(context.state->offset, v, out.depth);
    if (offset != 0.0) out.depth = planeThrough(v, z, out.minX, out.minY, offset);
    if (context.state->output != FragmentOutput::VaryingColor) return;
    // Perspective-correct interpolation: 1/w and a/w are affine in window space.
    const double inverseW[3] = {v[0].inverseW, v[1].inverseW, v[2].inverseW};
    planes.push_back(planeThrough(v, inverseW, out.minX, out.minY));
    for (int k = 0; k < context.varyingCount; ++k) {
        const double q[3] = {v[0].varyings[k] * v[0].inverseW, v[1].varyings[k] * v[1].inverseW,
                             v[2].varyings[k] * v[2].inverseW};
        planes.push_back(planeThrough(v, q, out.minX, out.minY));
    }
}

}  // namespace

bool setupTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, uint32_t primitiveId,
                   const SetupContext& context, TriangleSetup& out, std::vector<Plane>& planes) {
    if (!(a.position.w > 0.0f && b.position.w > 0.0f && c.position.w > 0.0f)) return false;
    WindowVertex v[3] = {toWindow(a, context.width, context.height), toWindow(b, context.width, context.height),
                         toWindow(c, context.width, context.height)};
    canonicalRotation(v);
    const int64_t det = (int64_t(v[1].x) - v[0].x) * (int64_t(v[2].y) - v[0].y) -
                        (int64_t(v[2].x) - v[0].x) * (int64_t(v[1].y) - v[0].y);
    if (det == 0) return false;
    // Counter-clockwise in NDC (y up) is clockwise in window space (y down): det < 0.
    out.frontFacing = det < 0;
    const CullMode cull = context.state->cull;
    if ((cull == CullMode::Back && !out.frontFacing) || (cull == CullMode::Front && out.frontFacing)) return false;

    const bool conservative = context.state->conservative;
    const PixelBounds bounds = pixelBounds(v, conservative, context.width, context.height);
    if (bounds.minX >= bounds.maxX || bounds.minY >= bounds.maxY) return false;
    out.minX = bounds.minX, out.minY = bounds.minY, out.maxX = bounds.maxX, out.maxY = bounds.maxY;
    setupEdges(v, det > 0 ? 1 : -1, conservative, out);
    out.primitiveId = primitiveId;
    out.varyings = nullptr;
    setupPlanes(v, context, out, planes);
    return true;
}

}  // namespace shadowlab::raster
