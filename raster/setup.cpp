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

// Rotate so the vertex with the smallest (y, x) comes first: the planes are then computed
// from the same base vertex however the triangle was submitted (llvmpipe warns that the
// same primitive rotated otherwise gives different z).
void canonicalRotation(SetupVertex v[3]) {
    int first = 0;
    for (int k = 1; k < 3; ++k) {
        const WindowVertex &a = v[k].window, &b = v[first].window;
        if (a.y < b.y || (a.y == b.y && a.x < b.x)) first = k;
    }
    const SetupVertex r[3] = {v[first], v[(first + 1) % 3], v[(first + 2) % 3]};
    for (int k = 0; k < 3; ++k) v[k] = r[k];
}

struct PixelBounds {
    int32_t minX, minY, maxX, maxY;
};

PixelBounds pixelBounds(const SetupVertex c[3], bool conservative, int width, int height) {
    int64_t lo[2] = {c[0].window.x, c[0].window.y}, hi[2] = {c[0].window.x, c[0].window.y};
    for (int k = 1; k < 3; ++k) {
        lo[0] = std::min<int64_t>(lo[0], c[k].window.x), hi[0] = std::max<int64_t>(hi[0], c[k].window.x);
        lo[1] = std::min<int64_t>(lo[1], c[k].window.y), hi[1] = std::max<int64_t>(hi[1], c[k].window.y);
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

void setupEdges(const SetupVertex c[3], int64_t sign, bool conservative, TriangleSetup& out) {
    for (int k = 0; k < 3; ++k) {
        const WindowVertex& a = c[k].window;
        const WindowVertex& b = c[(k + 1) % 3].window;
        const int64_t A = -sign * (int64_t(b.y) - a.y);
        const int64_t B = sign * (int64_t(b.x) - a.x);
        const int64_t C = -(A * a.x + B * a.y);
        const bool topLeft = A > 0 || (A == 0 && B > 0);
        const int64_t K = conservative ? kSubpixelHalf * (A + B) + C + (kSubpixelHalf + 1) * (std::abs(A) + std::abs(B))
                                       : kSubpixelHalf * (A + B) + C - (topLeft ? 0 : 1);
        out.edgeA[k] = int32_t(A);
        out.edgeB[k] = int32_t(B);
        out.edgeC[k] = K >> kSubpixelBits;   // floor(K / 256): C++20 shifts are arithmetic
    }
}

// What every attribute's plane over one triangle shares: the base vertex and the other two
// relative to it, in pixels, the inverse of their determinant, and the reference pixel.
struct PlaneBasis {
    double x0, y0, x1, y1, x2, y2, inverseDet;
    int32_t refX, refY;
};

PlaneBasis planeBasis(const SetupVertex c[3], int32_t refX, int32_t refY) {
    PlaneBasis b;
    b.x0 = c[0].window.x / double(kSubpixelOne), b.y0 = c[0].window.y / double(kSubpixelOne);
    b.x1 = c[1].window.x / double(kSubpixelOne) - b.x0, b.y1 = c[1].window.y / double(kSubpixelOne) - b.y0;
    b.x2 = c[2].window.x / double(kSubpixelOne) - b.x0, b.y2 = c[2].window.y / double(kSubpixelOne) - b.y0;
    b.inverseDet = 1.0 / (b.x1 * b.y2 - b.x2 * b.y1);
    b.refX = refX, b.refY = refY;
    return b;
}

// The affine function of window (x, y) taking values q[k] at the three vertices, in double:
// its value at the centre of the reference pixel and its slopes.
struct DoublePlane {
    double atRef, perX, perY;
};

DoublePlane planeThrough(const PlaneBasis& b, const double q[3]) {
    const double perX = ((q[1] - q[0]) * b.y2 - (q[2] - q[0]) * b.y1) * b.inverseDet;
    const double perY = ((q[2] - q[0]) * b.x1 - (q[1] - q[0]) * b.x2) * b.inverseDet;
    return {q[0] + perX * (b.refX + 0.5 - b.x0) + perY * (b.refY + 0.5 - b.y0), perX, perY};
}

// As the kernels take it: float, with `offset` added in double first.
Plane toKernelPlane(const DoublePlane& p, double offset = 0.0) {
    return {float(p.atRef + offset), float(p.perX), float(p.perY)};
}

// OpenGL 4.6 section 14.6.5: factor * max slope + units * r, where for a float depth
// buffer r = 2^(e - 23) and e is the exponent of the triangle's largest depth.
double polygonOffset(const PolygonOffset& offset, double maxDepth, const Plane& depth) {
    if (offset.factor == 0.0f && offset.units == 0.0f) return 0.0;
    const double maxSlope = std::max(std::abs(double(depth.perX)), std::abs(double(depth.perY)));
    int exponent = 0;
    std::frexp(maxDepth, &exponent);   // maxZ = m 2^exponent, m in [0.5, 1): IEEE exponent is exponent - 1
    const double r = std::ldexp(1.0, exponent - 1 - 23);
    return offset.factor * maxSlope + offset.units * r;
}

void setupPlanes(const SetupVertex v[3], double maxDepth, const SetupContext& context, TriangleSetup& out,
                 std::vector<Plane>& planes) {
    const PlaneBasis basis = planeBasis(v, out.minX, out.minY);
    const double z[3] = {v[0].window.z, v[1].window.z, v[2].window.z};
    const DoublePlane depth = planeThrough(basis, z);
    // The offset takes the slope of the float plane, and is added to the depth in double,
    // not to the float plane.
    out.depth = toKernelPlane(depth);
    out.depth = toKernelPlane(depth, polygonOffset(context.state->offset, maxDepth, out.depth));
    if (context.state->output != FragmentOutput::VaryingColor) return;
    // Perspective-correct interpolation: 1/w and a/w are affine in window space.
    const double inverseW[3] = {v[0].window.inverseW, v[1].window.inverseW, v[2].window.inverseW};
    planes.push_back(toKernelPlane(planeThrough(basis, inverseW)));
    for (int k = 0; k < context.varyingCount; ++k) {
        const double q[3] = {v[0].varyings[k] * inverseW[0], v[1].varyings[k] * inverseW[1],
                             v[2].varyings[k] * inverseW[2]};
        planes.push_back(toKernelPlane(planeThrough(basis, q)));
    }
}

}  // namespace

bool setupTriangle(const SetupVertex (&corners)[3], const Primitive& primitive, const SetupContext& context,
                   TriangleSetup& out, std::vector<Plane>& planes) {
    SetupVertex v[3] = {corners[0], corners[1], corners[2]};
    canonicalRotation(v);
    const WindowVertex &a = v[0].window, &b = v[1].window, &c = v[2].window;
    const int64_t det = (int64_t(b.x) - a.x) * (int64_t(c.y) - a.y) - (int64_t(c.x) - a.x) * (int64_t(b.y) - a.y);
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
    out.primitiveId = primitive.id;
    out.varyings = nullptr;
    setupPlanes(v, primitive.maxDepth, context, out, planes);
    return true;
}

}  // namespace shadowlab::raster
