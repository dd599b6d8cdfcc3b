// G-buffer reconstruction: one ray-plane intersection per covered pixel.
//
// Interpolating P from vertex attributes would inherit the rasterizer's fixed-point
// snapping and perspective-correct interpolation error; intersecting the exact pixel-centre
// ray with the triangle's plane in double gives the surface point to within the final
// rounding to float (half an ulp per component). The shadow reference relies on that bound
// for its ray offset (shadows/reference/reference.cpp).
//
// Threads own rows (tbb::parallel_for over j); every pixel is written exactly once from
// inputs no other pixel writes, so the result is the same for any thread count.
#include "shading/gbuffer_build.h"

#include <optional>
#include <stdexcept>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "scenes/camera.h"

namespace shadowlab {
namespace {

struct SurfacePoint {
    glm::dvec3 position;
    glm::dvec3 normal;  // unit, facing the ray origin
    glm::dvec3 barycentric;  // of position, weights of v0, v1, v2
};

// Ray-plane intersection (e.g. Shirley & Marschner, Fundamentals of Computer Graphics,
// 4.4.2): t = n.(v0 - o) / n.d with n the unnormalised triangle normal. Empty when the ray
// is parallel to the plane (or the triangle degenerate), where no intersection exists.
std::optional<SurfacePoint> intersectTrianglePlane(const RayD& ray, const glm::dvec3& v0,
                                    const glm::dvec3& v1, const glm::dvec3& v2) {
    const glm::dvec3 n = glm::cross(v1 - v0, v2 - v0);
    const double denominator = glm::dot(n, ray.direction);
    if (denominator == 0.0) {
        return std::nullopt;
    }
    const double t = glm::dot(n, v0 - ray.origin) / denominator;
    const glm::dvec3 p = ray.origin + t * ray.direction;
    const glm::dvec3 unitNormal = glm::normalize(n);
    // The ray arrives against the front of the surface it sees, so the camera-facing
    // normal points against the ray: dot(N, eye - P) = -t * dot(N, d) > 0 for t > 0.
    const bool facesCamera = glm::dot(unitNormal, ray.origin - p) > 0.0;
    // Each weight is the signed area of the sub-triangle with P in place of its vertex over
    // the whole, areas measured along n (Shirley & Marschner 2.7).
    const double area = glm::dot(n, n);
    const double b1 = glm::dot(n, glm::cross(p - v0, v2 - v0)) / area;
    const double b2 = glm::dot(n, glm::cross(v1 - v0, p - v0)) / area;
    return SurfacePoint{p, facesCamera ? unitNormal : -unitNormal, {1.0 - b1 - b2, b1, b2}};
}

// The corner normals of triangle t weighted by `barycentric`, normalised and on the side of
// the camera-facing geometric normal; the geometric normal where they cancel or are absent.
glm::vec3 shadingNormal(const WorldGeometry& world, uint32_t t, const SurfacePoint& s) {
    if (world.cornerNormals.empty()) return glm::vec3(s.normal);
    const glm::vec3* n = &world.cornerNormals[3 * size_t(t)];
    const glm::dvec3 sum = s.barycentric.x * glm::dvec3(n[0]) + s.barycentric.y * glm::dvec3(n[1]) +
                           s.barycentric.z * glm::dvec3(n[2]);
    const double length = glm::length(sum);
    if (!(length > 0.0)) return glm::vec3(s.normal);
    const glm::dvec3 unit = sum / length;
    return glm::vec3(glm::dot(unit, s.normal) < 0.0 ? -unit : unit);
}

// The corner UVs of triangle t weighted by `barycentric`: at the exact P, so perspective-correct.
glm::vec2 textureCoordinate(const WorldGeometry& world, uint32_t t, const SurfacePoint& s) {
    const glm::vec2* uv = &world.cornerUvs[3 * size_t(t)];
    return glm::vec2(s.barycentric.x * glm::dvec2(uv[0]) + s.barycentric.y * glm::dvec2(uv[1]) +
                     s.barycentric.z * glm::dvec2(uv[2]));
}

void writeBackground(GBuffer& g, size_t index) {
    g.hit[index] = 0;
    g.position[index] = glm::vec3(0.0f);
    g.normal[index] = glm::vec3(0.0f);
    g.shadingNormal[index] = glm::vec3(0.0f);
    g.material[index] = 0;
    g.triangle[index] = kNoTriangle;
    if (!g.uv.empty()) g.uv[index] = glm::vec2(0.0f);
    g.depth[index] = 1.0f;
}

std::string pixelName(int i, int j) {
    return "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

void writeSurface(GBuffer& g, size_t index, const WorldGeometry& world, const PixelRays& rays,
                  int i, int j, uint32_t triangle, float depth) {
    if (triangle >= world.triangles.size()) {
        throw std::invalid_argument("buildGBuffer: triangle index " + std::to_string(triangle) +
                                    " out of range at " + pixelName(i, j));
    }
    const glm::uvec3 t = world.triangles[triangle];
    const std::optional<SurfacePoint> s = intersectTrianglePlane(
        rays(i, j), glm::dvec3(world.positions[t.x]),
        glm::dvec3(world.positions[t.y]), glm::dvec3(world.positions[t.z]));
    if (!s) {
        throw std::invalid_argument("buildGBuffer: ray of " + pixelName(i, j) +
                                    " is parallel to triangle " + std::to_string(triangle));
    }
    g.hit[index] = 1;
    g.position[index] = glm::vec3(s->position);
    g.normal[index] = glm::vec3(s->normal);
    g.shadingNormal[index] = shadingNormal(world, triangle, *s);
    g.material[index] = world.triangleMaterial[triangle];
    g.triangle[index] = triangle;
    if (!g.uv.empty()) g.uv[index] = textureCoordinate(world, triangle, *s);
    g.depth[index] = depth;
}

}  // namespace

void requireConsistent(const GBuffer& g, const char* who) {
    const size_t n = g.pixelCount();
    const bool consistent = g.width >= 0 && g.height >= 0 && g.hit.size() == n && g.position.size() == n &&
                            g.normal.size() == n && g.shadingNormal.size() == n && g.material.size() == n && g.triangle.size() == n &&
                            (g.uv.empty() || g.uv.size() == n) && g.depth.size() == n;
    const SurfaceMotion& m = g.motion;
    const bool motionConsistent = m.pixelOffset.size() == m.previousPosition.size() &&
                                  m.pixelOffset.size() == m.previousNormal.size() &&
                                  (m.pixelOffset.empty() || m.pixelOffset.size() == n);
    if (!consistent || !motionConsistent) {
        throw std::invalid_argument(std::string(who) + ": G-buffer arrays do not all have " +
                                    std::to_string(g.width) + " x " + std::to_string(g.height) + " entries");
    }
}

GBuffer buildGBuffer(const WorldGeometry& world, const Camera& camera,
                     const std::vector<uint32_t>& visibleTriangle,
                     const std::vector<float>& depth) {
    GBuffer g;
    g.width = camera.width;
    g.height = camera.height;
    const size_t n = g.pixelCount();
    if (visibleTriangle.size() != n || depth.size() != n) {
        throw std::invalid_argument("buildGBuffer: visibility/depth buffers have " +
                                    std::to_string(visibleTriangle.size()) + "/" +
                                    std::to_string(depth.size()) + " entries, camera has " +
                                    std::to_string(n) + " pixels");
    }
    if (world.triangleMaterial.size() != world.triangles.size()) {
        throw std::invalid_argument("buildGBuffer: triangleMaterial size differs from triangles");
    }
    if (!world.cornerNormals.empty() && world.cornerNormals.size() != 3 * world.triangles.size()) {
        throw std::invalid_argument("buildGBuffer: " + std::to_string(world.cornerNormals.size()) +
                                    " corner normals for " + std::to_string(world.triangles.size()) + " triangles");
    }
    if (!world.cornerUvs.empty() && world.cornerUvs.size() != 3 * world.triangles.size()) {
        throw std::invalid_argument("buildGBuffer: " + std::to_string(world.cornerUvs.size()) +
                                    " corner UVs for " + std::to_string(world.triangles.size()) + " triangles");
    }
    g.hit.resize(n);
    g.position.resize(n);
    g.normal.resize(n);
    g.shadingNormal.resize(n);
    g.material.resize(n);
    g.triangle.resize(n);
    if (!world.cornerUvs.empty()) g.uv.resize(n);
    g.depth.resize(n);

    const PixelRays rays(camera);
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j != rows.end(); ++j) {
            for (int i = 0; i < g.width; ++i) {
                const size_t index = g.index(i, j);
                if (visibleTriangle[index] == kNoTriangle) {
                    writeBackground(g, index);
                } else {
                    writeSurface(g, index, world, rays, i, j, visibleTriangle[index], depth[index]);
                }
            }
        }
    });
    return g;
}

}  // namespace shadowlab
