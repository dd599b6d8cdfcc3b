// The exact reference against closed-form answers:
//  (a) a square occluder over a plane: the hard shadow is the square projected from the
//      light, so V must match an inside/outside test at every point not within a tiny
//      distance of the outline, near the origin and far from it (where rounding is
//      coarse and the ray offset must scale);
//  (b) a disk (and a rectangle) light over the straight edge of a half-plane occluder: the
//      visible fraction is the area of the light on one side of a line, a circular
//      segment for the disk; the stratified estimate must be within a bound derived from
//      the strata the line crosses; likewise a sun with an angular size, the solid angle
//      of its cap on one side of a great circle (a circular segment of the sun's disk on
//      the sky, to the order of its angular size squared);
//  and the result must be the same bytes for 1 and 2 threads, and with progress reported.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>

#include "raster/thread_count.h"
#include "shading/light_sampling.h"
#include "shadows/reference/reference.h"
#include "shadows/technique.h"
#include "tests/same_bits.h"

using namespace shadowlab;

namespace {

// Two triangles a b c, a c d (counter-clockwise as listed).
void addQuad(WorldGeometry& w, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
             const glm::dvec3& d) {
    const uint32_t base = uint32_t(w.positions.size());
    for (const glm::dvec3& p : {a, b, c, d}) w.positions.push_back(glm::vec3(p));
    w.triangles.push_back({base, base + 1, base + 2});
    w.triangles.push_back({base, base + 2, base + 3});
    for (int k = 0; k < 2; ++k) {
        w.triangleMaterial.push_back(0);
        w.triangleInstance.push_back(0);
    }
}

// A plane through `origin` with unit normal, and an orthonormal basis (e1, e2) in it.
struct Plane {
    glm::dvec3 origin, normal, e1, e2;
    Plane(const glm::dvec3& o, const glm::dvec3& n) : origin(o), normal(glm::normalize(n)) {
        e1 = glm::normalize(glm::dvec3(1.0, 0.0, 0.0) - normal * normal.x);
        e2 = glm::cross(normal, e1);  // e1 x e2 = normal
    }
    glm::dvec3 at(double u, double v) const { return origin + u * e1 + v * e2; }
};

void addPlaneQuad(WorldGeometry& w, const Plane& p, double halfSize) {
    const double h = halfSize;
    addQuad(w, p.at(-h, -h), p.at(h, -h), p.at(h, h), p.at(-h, h));
}

GBuffer emptyGBuffer(int width, int height) {
    GBuffer g;
    g.width = width;
    g.height = height;
    const size_t n = g.pixelCount();
    g.hit.assign(n, 0);
    g.position.assign(n, glm::vec3(0.0f));
    g.normal.assign(n, glm::vec3(0.0f));
    g.shadingNormal.assign(n, glm::vec3(0.0f));
    g.material.assign(n, 0);
    g.triangle.assign(n, kNoTriangle);
    g.depth.assign(n, 1.0f);
    return g;
}

void setSurface(GBuffer& g, size_t k, const glm::dvec3& P, const glm::dvec3& N) {
    g.hit[k] = 1;
    g.position[k] = glm::vec3(P);  // rounded to float, as buildGBuffer does
    g.normal[k] = glm::vec3(N);
    g.shadingNormal[k] = glm::vec3(N);
    g.depth[k] = 0.5f;
}

// n x n points of the plane over [-halfSize, halfSize]^2; G-buffers need no rasterizer.
GBuffer planeGrid(const Plane& plane, int n, double halfSize) {
    GBuffer g = emptyGBuffer(n, n);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double u = -halfSize + 2.0 * halfSize * i / (n - 1);
            const double v = -halfSize + 2.0 * halfSize * j / (n - 1);
            setSurface(g, g.index(i, j), plane.at(u, v), plane.normal);
        }
    }
    return g;
}

// ---- (a) square occluder -------------------------------------------------------------
// Receiver: a plane through T with normal `tilt`. Occluder: the 1 m square
// |x - T.x|, |z - T.z| <= 0.5 at height T.y + 1. Light: a point light at T + offset, or a
// directional light.
struct SquareScene {
    glm::dvec3 T;
    Plane receiver;
    double occluderY;
    WorldGeometry world;
    SquareScene(const glm::dvec3& t, const glm::dvec3& tilt)
        : T(t), receiver(t, tilt), occluderY(t.y + 1.0) {
        addPlaneQuad(world, receiver, 20.0);
        addQuad(world, T + glm::dvec3(-0.5, 1.0, -0.5), T + glm::dvec3(-0.5, 1.0, 0.5),
                T + glm::dvec3(0.5, 1.0, 0.5), T + glm::dvec3(0.5, 1.0, -0.5));
    }
    // Where the ray from P towards the light crosses the occluder's plane, relative to T;
    // its max-norm minus 0.5 is the signed distance (max-norm) from the square's outline.
    double signedDistanceToOutline(const glm::dvec3& P, const Light& light) const {
        glm::dvec3 Q;
        if (light.type == LightType::Directional) {
            const glm::dvec3 d(light.direction);
            Q = P + d * ((occluderY - P.y) / d.y);
        } else {
            const glm::dvec3 L(light.position);
            Q = L + (P - L) * ((L.y - occluderY) / (L.y - P.y));
        }
        return std::max(std::abs(Q.x - T.x), std::abs(Q.z - T.z)) - 0.5;
    }
};

void checkSquareShadow(const SquareScene& scene, const Light& light) {
    const ReferenceVisibility reference(scene.world, nullptr);
    const int n = 81;
    const GBuffer g = planeGrid(scene.receiver, n, 2.5);
    const uint64_t raysBefore = reference.raysCast();
    const std::vector<float> V = reference.visibility(g, light);
    CHECK(reference.raysCast() - raysBefore == uint64_t(n * n));  // every point faces the light

    int lit = 0, shadowed = 0, nearOutline = 0;
    for (size_t k = 0; k < g.pixelCount(); ++k) {
        const glm::dvec3 P(g.position[k]);
        const double distance = scene.signedDistanceToOutline(P, light);
        // The ray offset moves a shadow ray by about the offset, and Embree's edge tests are
        // good to a few float ulps of the scene's size, both far below 8 offsets.
        const double margin = 8.0 * reference.shadowRayOffset(g.position[k]);
        if (std::abs(distance) <= margin) {
            ++nearOutline;
            continue;
        }
        const float expected = distance < 0.0 ? 0.0f : 1.0f;
        (expected == 0.0f ? shadowed : lit) += 1;
        if (V[k] != expected) {
            CAPTURE(k);
            CAPTURE(distance);
            CHECK(V[k] == expected);
        }
    }
    CHECK(shadowed > 200);
    CHECK(lit > 3000);
    CHECK(nearOutline < n * n / 100);  // the test is not vacuous
}

// ---- (b) area light over a half-plane edge --------------------------------------------
// Ground y = 0; occluder: the half-plane x < 0 at height h = 2; light centred at (0, 4, 0)
// facing down. A light point S is hidden from P = (x, 0, z) iff the segment crosses y = h
// at x < 0, i.e. iff S.x < x * (h - H) / h = -x for H = 4: the visible part of the light
// is the part with S.x >= -x.
constexpr double kOccluderY = 2.0, kLightY = 4.0;

WorldGeometry halfPlaneGeometry() {
    WorldGeometry w;
    addQuad(w, {-20.0, 0.0, -20.0}, {-20.0, 0.0, 20.0}, {20.0, 0.0, 20.0}, {20.0, 0.0, -20.0});
    addQuad(w, {-20.0, kOccluderY, -20.0}, {-20.0, kOccluderY, 20.0}, {0.0, kOccluderY, 20.0},
            {0.0, kOccluderY, -20.0});
    return w;
}

double hiddenBelowX(double receiverX) { return receiverX * (kOccluderY - kLightY) / kOccluderY; }

// Area fraction of the disk of radius R with x - centre >= d: the circular segment
// R^2 acos(d/R) - d sqrt(R^2 - d^2) over pi R^2 (clamped outside [-R, R]).
double diskFractionRightOf(double d, double R) {
    if (d <= -R) return 1.0;
    if (d >= R) return 0.0;
    return (R * R * std::acos(d / R) - d * std::sqrt(R * R - d * d)) / (std::numbers::pi * R * R);
}

// Which side of the occluder's edge a sample u in [0, 1)^2 of the light falls on: the
// sample is visible iff its coordinate >= the receiver's edge.
using SampleCoordinate = std::function<double(const glm::dvec2& u)>;

// Range of the coordinate covered by each stratum, from a (sub+1)^2 grid of points per
// stratum, widened by the largest step between neighbouring grid points (the map is smooth
// within a stratum, so the true range exceeds the sampled one by less).
struct Range {
    double lo, hi;
};
std::vector<Range> strataRanges(const SampleCoordinate& coordinate, int n, int sub) {
    std::vector<Range> ranges;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            Range r{1e300, -1e300};
            double step = 0.0;
            for (int q = 0; q <= sub; ++q) {
                double previous = 0.0;
                for (int p = 0; p <= sub; ++p) {
                    const glm::dvec2 u((a + double(p) / sub) / n, (b + double(q) / sub) / n);
                    const double x = coordinate(u);
                    r.lo = std::min(r.lo, x);
                    r.hi = std::max(r.hi, x);
                    if (p > 0) step = std::max(step, std::abs(x - previous));
                    previous = x;
                }
            }
            ranges.push_back({r.lo - step, r.hi + step});
        }
    }
    return ranges;
}

// Stratified estimate of a visible fraction, one jittered sample per stratum, N = n^2:
// strata wholly on one side of the occluder's edge contribute exactly; each of the K
// strata the edge crosses contributes an independent term in [0, 1/N] with the right
// mean. Hoeffding's inequality bounds the error: P(|error| >= t) <= 2 exp(-2 t^2 N^2 / K),
// so |error| < t = sqrt(K ln(2/delta) / 2) / N except with probability delta.
// The test uses delta = 1e-6 per point (so it would pass for almost any seed); the ray
// offset (micrometres) moves the edge by far less than the 1e-4 added for it.
// A light's samples against the edge: which side each falls on, the edge's place for a
// receiver at x, and the exact visible fraction for an edge.
struct Profile {
    SampleCoordinate coordinate;
    std::function<double(double receiverX)> edge;
    std::function<double(double edge)> exactFraction;
    double halfWidth = 0.7;   // the receivers' x in [-halfWidth, halfWidth]
};

// An area light's: the x of its point, hidden below hiddenBelowX of the receiver's x.
Profile areaLightProfile(const Light& light, double (*exactFraction)(const Light&, double hiddenBelow)) {
    const AreaLightFrame frame = areaLightFrame(light);
    return {[frame](const glm::dvec2& u) { return areaLightPoint(frame, u).x; }, hiddenBelowX,
            [light, exactFraction](double edge) { return exactFraction(light, edge); }};
}

void checkProfile(const Light& light, const Profile& profile) {
    const ReferenceVisibility reference(halfPlaneGeometry(), nullptr);
    const ReferenceOptions options;  // 32 x 32
    const int n = options.areaSamplesPerAxis, samples = n * n;
    const std::vector<Range> ranges = strataRanges(profile.coordinate, n, 16);
    const double delta = 1e-6;

    const int points = 71;
    GBuffer g = emptyGBuffer(points, 1);
    for (int i = 0; i < points; ++i) {
        setSurface(g, size_t(i), {profile.halfWidth * (-1.0 + i / 35.0), 0.0, 0.37}, {0.0, 1.0, 0.0});
    }
    const std::vector<float> V = reference.visibility(g, light, options);
    double sumError = 0.0, sumK = 0.0;
    int penumbra = 0;
    for (int i = 0; i < points; ++i) {
        const double xc = profile.edge(double(g.position[size_t(i)].x));
        const double exact = profile.exactFraction(xc);
        const auto K = std::count_if(ranges.begin(), ranges.end(),
                                     [xc](const Range& r) { return r.lo <= xc && xc <= r.hi; });
        const double bound = std::sqrt(double(K) * std::log(2.0 / delta) / 2.0) / samples + 1e-4;
        CAPTURE(i);
        CAPTURE(exact);
        CAPTURE(K);
        CHECK(std::abs(V[size_t(i)] - exact) <= bound);
        sumError += V[size_t(i)] - exact;
        sumK += double(K);
        penumbra += exact > 0.0 && exact < 1.0;
    }
    CHECK(penumbra > 40);
    // The mean of the independent errors has standard deviation <= sqrt(sum K) / (2 N M):
    // a biased sampler (say, a map that does not preserve area) fails this long before
    // any single point leaves its bound.
    CHECK(std::abs(sumError / points) <= 5.0 * std::sqrt(sumK) / (2.0 * samples * points));
}

// The share of a sun's cap whose directions d have dot(d, n) >= 0, n the unit normal of a
// great circle. In polar coordinates (theta, phi) about the cap's axis a, with
// sin delta = dot(a, n), the circle of polar angle theta is on that side where
// cos phi >= -tan delta cot theta; cos theta is uniform on [cos theta_max, 1] over the cap,
// so the share is the mean of acos(clamp(-tan delta cot theta)) / pi over it (midpoint rule,
// cos theta = 1 - h s, sin theta = sqrt(h s (2 - h s)) to keep the digits of a small cap).
double capShareAbove(const SunCap& cap, const glm::dvec3& n) {
    const double sinDelta = glm::dot(cap.axis, n), tanDelta = sinDelta / std::sqrt(1.0 - sinDelta * sinDelta);
    const int steps = 200000;
    double sum = 0.0;
    for (int k = 0; k < steps; ++k) {
        const double hs = cap.oneMinusCosMax * (k + 0.5) / steps;
        const double cotTheta = (1.0 - hs) / std::sqrt(hs * (2.0 - hs));
        sum += std::acos(std::clamp(-tanDelta * cotTheta, -1.0, 1.0));
    }
    return sum / (steps * std::numbers::pi);
}

// A sun of 3 degrees above the half-plane, tilted along z so that its penumbra stays
// centred on x = 0. A direction d from P = (x, 0, z) passes the occluder iff it reaches
// y = h at x >= 0: d.x / d.y >= -x / h, the side of the great circle of normal (1, -c, 0)
// with c = -x / h.
Light sunOverEdge() {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.0f, 1.0f, 0.3f));
    sun.angularDiameterDeg = 3.0f;
    return sun;
}

Light diskLight() {
    Light disk;
    disk.type = LightType::Disk;
    disk.position = {0.0f, float(kLightY), 0.0f};
    disk.direction = {0.0f, -1.0f, 0.0f};
    disk.radius = 0.5f;
    return disk;
}

// A disk light over the square's receiver grid: a penumbra over many of its pixels.
Light diskOverSquare() {
    Light disk = diskLight();
    disk.position = {0.3f, 3.0f, 0.2f};
    disk.radius = 0.4f;
    return disk;
}

}  // namespace

TEST_CASE("point light over a square occluder: V is the projected square, exactly") {
    SUBCASE("near the origin, flat receiver") {
        const SquareScene scene({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
        Light light;
        light.position = {0.3f, 3.0f, 0.2f};
        checkSquareShadow(scene, light);
    }
    SUBCASE("far from the origin, tilted receiver (rounded P, scale-aware offset)") {
        const SquareScene scene({300.0, 20.0, -200.0}, {0.1, 1.0, -0.05});
        Light light;
        light.position = glm::vec3(scene.T + glm::dvec3(0.3, 3.0, 0.2));
        checkSquareShadow(scene, light);
    }
}

TEST_CASE("directional light over a square occluder: V is the parallel projection") {
    const SquareScene scene({300.0, 20.0, -200.0}, {-0.08, 1.0, 0.1});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.2f, 1.0f, 0.1f};
    checkSquareShadow(scene, sun);
}

TEST_CASE("disk light over a half-plane edge: the visible fraction is a circular segment") {
    checkProfile(diskLight(), areaLightProfile(diskLight(), [](const Light& light, double hiddenBelow) {
                     return diskFractionRightOf(hiddenBelow - double(light.position.x), double(light.radius));
                 }));
}

TEST_CASE("rectangle light over a half-plane edge: the visible fraction is linear") {
    Light rectangle = diskLight();
    rectangle.type = LightType::Rectangle;
    rectangle.halfEdgeU = {0.5f, 0.0f, 0.0f};
    rectangle.halfEdgeV = {0.0f, 0.0f, 0.3f};
    checkProfile(rectangle, areaLightProfile(rectangle, [](const Light& light, double hiddenBelow) {
                     const double right = double(light.position.x + light.halfEdgeU.x), width = 2.0 * light.halfEdgeU.x;
                     return std::clamp((right - hiddenBelow) / width, 0.0, 1.0);
                 }));
}

TEST_CASE("sun with an angular size over a half-plane edge: the visible share of its cap") {
    const SunCap cap = sunCap(sunOverEdge());
    const Profile profile{
        .coordinate = [cap](const glm::dvec2& u) {
            const glm::dvec3 d = sunCapDirection(cap, concentricSquareToDisk(u));
            return d.x / d.y;
        },
        .edge = [](double receiverX) { return -receiverX / kOccluderY; },
        .exactFraction = [cap](double c) { return capShareAbove(cap, glm::normalize(glm::dvec3(1.0, -c, 0.0))); },
        .halfWidth = 0.075};   // the penumbra: |x| < about h tan(1.5 degrees) / cos(16.7 degrees)
    checkProfile(sunOverEdge(), profile);
}

TEST_CASE("a sun's cap cut by a great circle is a circular segment of its disk on the sky, to O(theta_max^2)") {
    const SunCap cap = sunCap(sunOverEdge());
    const double thetaMax = 1.5 * std::numbers::pi / 180.0;
    for (double offset : {-1.2, -0.8, -0.3, 0.0, 0.5, 0.9, 1.1}) {   // the circle's distance from the centre, in theta_max
        // The great circle at angle delta = offset theta_max from the axis, tilted about x.
        const double delta = offset * thetaMax;
        const glm::dvec3 n = glm::normalize(glm::dvec3(std::cos(delta), 0.0, 0.0) + std::sin(delta) * cap.axis);
        CAPTURE(offset);
        CHECK(std::abs(capShareAbove(cap, n) - diskFractionRightOf(-delta, thetaMax)) <= thetaMax * thetaMax);
    }
}

TEST_CASE("a sun of size 0 is one ray per pixel, and the hard techniques see a sized sun's centre direction") {
    const SquareScene scene({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
    const ReferenceVisibility reference(scene.world, nullptr);
    const int n = 40;
    const GBuffer g = planeGrid(scene.receiver, n, 2.0);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f));
    const uint64_t before = reference.raysCast();
    const std::vector<float> point = reference.visibility(g, sun);
    CHECK(reference.raysCast() - before == uint64_t(n * n));
    Light sized = sun;
    sized.angularDiameterDeg = 10.0f;
    CHECK(test::sameBytes(reference.visibility(g, pointLightFor(sized)), point));
    // The sized sun itself: a penumbra around the hard outline, the same V far from it.
    const std::vector<float> soft = reference.visibility(g, sized, {.areaSamplesPerAxis = 8});
    int penumbra = 0, differ = 0;
    for (size_t k = 0; k < soft.size(); ++k) {
        penumbra += soft[k] > 0.0f && soft[k] < 1.0f;
        // Beyond the outline by more than the penumbra's half-width in the occluder's plane,
        // 1 m up: under 1.1 m x tan(5 degrees) < 0.1.
        differ += std::abs(scene.signedDistanceToOutline(glm::dvec3(g.position[k]), sun)) > 0.15 && soft[k] != point[k];
    }
    CHECK(penumbra > 50);
    CHECK(differ == 0);
}

TEST_CASE("no light from behind the surface, outside a spot cone, or on background pixels") {
    WorldGeometry world;
    addQuad(world, {-5.0, 0.0, -5.0}, {-5.0, 0.0, 5.0}, {5.0, 0.0, 5.0}, {5.0, 0.0, -5.0});
    const ReferenceVisibility reference(world, nullptr);
    GBuffer g = emptyGBuffer(3, 1);
    setSurface(g, 0, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
    setSurface(g, 1, {1.0, 0.0, 0.0}, {0.0, -1.0, 0.0});  // seen from below: light behind it

    Light point;
    point.position = {0.0f, 1.0f, 0.0f};
    CHECK(reference.visibility(g, point) == std::vector<float>{1.0f, 0.0f, 0.0f});
    Light spot = point;
    spot.type = LightType::Spot;
    spot.direction = {1.0f, -0.1f, 0.0f};
    CHECK(reference.visibility(g, spot) == std::vector<float>{0.0f, 0.0f, 0.0f});
    spot.direction = {0.1f, -1.0f, 0.0f};
    CHECK(reference.visibility(g, spot) == std::vector<float>{1.0f, 0.0f, 0.0f});
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {0.3f, -1.0f, 0.0f};  // below the horizon of pixel 0
    CHECK(reference.visibility(g, sun) == std::vector<float>{0.0f, 1.0f, 0.0f});
    // A disk straddling the receiver's plane: the half below it does not count.
    Light disk = diskLight();
    disk.position = {0.0f, 0.0f, 0.0f};
    disk.direction = {1.0f, 0.0f, 0.0f};
    const std::vector<float> V = reference.visibility(g, disk);
    CHECK(V[0] == doctest::Approx(0.5).epsilon(0.05));
    CHECK(V[2] == 0.0f);
}

TEST_CASE("the reference gives the same bytes for 1 and 2 threads") {
    const SquareScene scene({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
    const ReferenceVisibility reference(scene.world, nullptr);
    const GBuffer g = planeGrid(scene.receiver, 32, 2.0);
    const Light disk = diskOverSquare();
    auto run = [&](int threads) {
        return withThreads(threads, [&] { return reference.visibility(g, disk); });  // default 32 x 32 samples
    };
    const std::vector<float> one = run(1), two = run(2);
    REQUIRE(one.size() == two.size());
    CHECK(test::sameBytes(one, two));
    CHECK(std::count_if(one.begin(), one.end(), [](float v) { return v > 0.0f && v < 1.0f; }) > 50);
}

TEST_CASE("reporting progress counts every row and does not change V") {
    const SquareScene scene({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0});
    const ReferenceVisibility reference(scene.world, nullptr);
    const GBuffer g = planeGrid(scene.receiver, 32, 2.0);
    const Light disk = diskOverSquare();
    // A clock that moves a second per reading, so that the line is drawn at once.
    std::atomic<int> seconds{0};
    std::ostringstream out;
    Progress progress(out, [&] { return Progress::Clock::time_point(std::chrono::seconds(seconds++)); });
    const std::vector<float> reported = withThreads(2, [&] { return reference.visibility(g, disk, {.progress = &progress}); });
    CHECK(reported == reference.visibility(g, disk));
    const std::string text = out.str();
    CHECK(text.find("\rreference rays: row 32/32 (100%), ") != std::string::npos);
    CHECK(text.back() == '\n');
}
