#include "shadows/maps/shadow_lookup.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "raster/portable_math.h"

namespace shadowlab {
namespace {

glm::dvec2 texelOf(const DepthMap& map, const glm::dvec3& p) {
    const glm::dvec4 h = map.texelFromWorld * glm::dvec4(p, 1.0);
    return glm::dvec2(h) / h.w;
}

// Where the ray through the centre of pixel (i, j) meets the plane (P, N).
glm::dvec3 onPlane(const PixelRays& rays, int i, int j, const glm::dvec3& P, const glm::dvec3& N) {
    const RayD ray = rays(i, j);
    return ray.origin + ray.direction * (glm::dot(N, P - ray.origin) / glm::dot(N, ray.direction));
}

LookupMap lookupMapOf(const DepthMap& map) {
    LookupMap out{};
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            out.texelFromWorld[4 * c + r] = float(map.texelFromWorld[c][r]);
            out.worldFromTexel[4 * c + r] = float(map.worldFromTexel[c][r]);
        }
    }
    out.depth = map.depth.data();
    out.size = map.size;
    out.tilesX = map.tilesX;
    return out;
}

static_assert(int(BiasMode::Constant) == kLookupConstant && int(BiasMode::SlopeScaled) == kLookupSlopeScaled &&
              int(BiasMode::NormalOffset) == kLookupNormalOffset && int(BiasMode::ReceiverPlane) == kLookupReceiverPlane);
static_assert(int(FilterKind::Nearest) == kLookupNearest && int(FilterKind::Bilinear) == kLookupBilinear &&
              int(FilterKind::Grid) == kLookupGrid && int(FilterKind::Poisson) == kLookupPoisson);

}  // namespace

const LookupKernels& lookupKernels(raster::SimdLevel simd) {
    return raster::forSimdLevel(simd, lookupKernelsScalar, lookupKernelsAvx2, lookupKernelsAvx512);
}

struct LookupPass::Tables {
    Tables(std::span<const DepthMap> maps, const Light& light, const BiasSettings& bias, const PcfKernel& kernel,
           int filter, raster::SimdLevel simd);
    LightReach reaches;       // where the float test cannot certify its answer
    std::vector<LookupMap> maps;
    std::vector<float> diskX, diskY, searchX, searchY;
    LookupConstants constants{};
    // The SIMD level's stages, and the scalar twins that take each row's tail.
    LookupKernel reach = nullptr, project = nullptr, filter = nullptr;
    LookupKernel scalarReach = nullptr, scalarProject = nullptr, scalarFilter = nullptr;
    int width = 1;
    bool rotated = false;     // the filter turns a Poisson disk per pixel
    std::vector<float> rotationCos, rotationSin;   // rotated: per angle of pcf.h, its cosine and sine
    RotationNoise rotationNoise = RotationNoise::Hash;   // rotated: which angle a pixel takes
    uint64_t frame = 0;                                  // the kernel's frame, for that noise
    bool soft = false;        // pcss, chs, blocker search: it reads the receivers' distance, writes d_o
    bool penumbra = false;    // pcss, chs: it writes the penumbra's width too
    bool proving = false;     // pcss with a hierarchy: it writes the known taps too
    bool chs = false;         // it writes the blocker search's level too
    // pcss, chs, blocker search: the light's width (eq. 7.6) and the perspective map's planes.
    void setSoft(const DepthMap& map, const glm::dvec2& lightTexels);
    // pcss, blocker search: the search's disk and region.
    void setSearch(const PcfKernel& search, double region);
};

LookupPass::Tables::Tables(std::span<const DepthMap> depthMaps, const Light& light, const BiasSettings& bias,
                           const PcfKernel& kernel, int filterIndex, raster::SimdLevel simd)
    : reaches(light) {
    // served[] holds 1 + a map's index in the low seven bits of a byte (kReachUndecided).
    if (depthMaps.size() > 126) throw std::invalid_argument("shadow lookup: more than 126 maps");
    for (const DepthMap& map : depthMaps) maps.push_back(lookupMapOf(map));
    for (const glm::dvec2& d : kernel.disk) diskX.push_back(float(d.x)), diskY.push_back(float(d.y));
    LookupConstants& c = constants;
    c.maps = maps.data();
    c.mapCount = int(maps.size());
    c.bias = int(bias.mode);
    c.constantMetres = float(bias.constantMetres);
    c.normalOffsetTexels = float(bias.normalOffsetTexels);
    c.directional = light.type == LightType::Directional;
    const glm::vec3 towards = c.directional ? glm::vec3(glm::normalize(glm::dvec3(light.direction))) : light.position;
    c.light[0] = towards.x, c.light[1] = towards.y, c.light[2] = towards.z;
    const glm::vec3 anchor = c.directional ? light.direction : light.position;   // as lightReaches
    c.reachAnchor[0] = anchor.x, c.reachAnchor[1] = anchor.y, c.reachAnchor[2] = anchor.z;
    c.spot = light.type == LightType::Spot;
    c.gridSize = kernel.settings.gridSize;
    c.diskX = diskX.data(), c.diskY = diskY.data();
    c.diskTaps = int(diskX.size());
    c.radiusTexels = float(kernel.settings.poissonRadiusTexels);
    const int plane = bias.mode == BiasMode::ReceiverPlane ? 1 : 0;
    const LookupKernels& vector = lookupKernels(simd);
    const LookupKernels& scalar = lookupKernelsScalar();
    reach = vector.reach, project = vector.project[plane], filter = vector.filter[filterIndex][plane];
    scalarReach = scalar.reach, scalarProject = scalar.project[plane], scalarFilter = scalar.filter[filterIndex][plane];
    width = vector.width;
    rotated = filterIndex == kLookupPoisson || filterIndex == kLookupPcss || filterIndex == kLookupBlockerSearch;
    penumbra = filterIndex == kLookupPcss || filterIndex == kLookupChs;
    soft = penumbra || filterIndex == kLookupBlockerSearch;
    rotationNoise = kernel.settings.rotation, frame = kernel.frame;
    for (int a = 0; rotated && a < kPoissonRotations; ++a) {
        rotationCos.push_back(float(portable::cos(poissonRotationAngle(a))));
        rotationSin.push_back(float(portable::sin(poissonRotationAngle(a))));
    }
}

LookupPass::LookupPass(std::span<const DepthMap> maps, const Light& light, const BiasSettings& bias,
                       const PcfKernel& kernel, raster::SimdLevel simd)
    : tables_(std::make_unique<Tables>(maps, light, bias, kernel, int(kernel.settings.kind), simd)) {}

LookupPass::LookupPass(const DepthMap& map, const Light& light, const Pcss& pcss, raster::SimdLevel simd) {
    BiasSettings plane;
    plane.mode = BiasMode::ReceiverPlane;
    tables_ = std::make_unique<Tables>(std::span(&map, 1), light, plane, pcss.filter, kLookupPcss, simd);
    Tables& t = *tables_;
    t.setSearch(pcss.search, pcss.searchRegion);
    t.setSoft(map, pcss.lightTexels);
    t.maps[0].hierarchy = pcss.hierarchy;
    t.proving = pcss.hierarchy != nullptr;
}

LookupPass::LookupPass(const DepthMap& map, const Light& light, const Chs& chs, raster::SimdLevel simd) {
    BiasSettings plane;
    plane.mode = BiasMode::ReceiverPlane;
    tables_ = std::make_unique<Tables>(std::span(&map, 1), light, plane, PcfKernel{}, kLookupChs, simd);
    Tables& t = *tables_;
    t.constants.searchNodes = chs.searchNodes, t.constants.filterNodes = chs.filterNodes;
    t.setSoft(map, chs.lightTexels);
    t.maps[0].hierarchy = &chs.hierarchy;
    t.chs = true;
}

LookupPass::LookupPass(const DepthMap& map, const Light& light, const BlockerSearch& search, raster::SimdLevel simd) {
    BiasSettings plane;
    plane.mode = BiasMode::ReceiverPlane;
    tables_ = std::make_unique<Tables>(std::span(&map, 1), light, plane, PcfKernel{}, kLookupBlockerSearch, simd);
    tables_->setSearch(search.search, search.searchRegion);
    tables_->setSoft(map, search.lightTexels);
}

void LookupPass::Tables::setSearch(const PcfKernel& search, double region) {
    for (const glm::dvec2& d : search.disk) searchX.push_back(float(d.x)), searchY.push_back(float(d.y));
    constants.searchX = searchX.data(), constants.searchY = searchY.data(), constants.searchTaps = int(searchX.size());
    constants.searchRegion = float(region);
}

void LookupPass::Tables::setSoft(const DepthMap& map, const glm::dvec2& lightTexels) {
    constants.lightTexels[0] = float(lightTexels.x), constants.lightTexels[1] = float(lightTexels.y);
    constants.zNear = float(map.view.zNear), constants.zFar = float(map.view.zFar);
}

LookupPass::~LookupPass() = default;

// The G-buffer's vectors are read as packed x, y, z floats.
static_assert(sizeof(glm::vec3) == 3 * sizeof(float));

void LookupPass::lookUpRow(const GBuffer& g, int j, Scratch& scratch, const Outputs& out) const {
    const Tables& t = *tables_;
    if ((t.soft && !out.blockerDistance) || (t.penumbra && !out.penumbraWidth)) {
        throw std::invalid_argument("shadow lookup: a soft pass writes the blocker distance, and the penumbra width");
    }
    if (t.proving && !out.knownTaps) throw std::invalid_argument("shadow lookup: a hierarchy's pass writes known taps");
    if (t.chs && !out.searchLevel) throw std::invalid_argument("shadow lookup: a chs pass writes the search level");
    const int count = g.width;
    if (t.rotated) {
        // The per-pixel rotation of the Poisson disk, the kernel's noise (pcf.h).
        for (int i = 0; i < count; ++i) {
            const int a = poissonRotationIndex(t.rotationNoise, t.frame, i, j, g.width);
            scratch.rotationCos[size_t(i)] = t.rotationCos[size_t(a)], scratch.rotationSin[size_t(i)] = t.rotationSin[size_t(a)];
        }
    }
    float* r = scratch.receivers.data();
    const int n = int(scratch.served.size());
    const ReceiverArrays arrays{r, r + n, r + 2 * n, r + 3 * n, r + 4 * n, r + 5 * n, t.soft ? r + 6 * n : nullptr};
    const size_t k = g.index(0, j);
    const int vectors = count - count % t.width;
    const auto image = [&](float* a, int at) { return a ? a + k + size_t(at) : a; };
    const LookupRow row{glm::value_ptr(g.position[k]), glm::value_ptr(g.normal[k]), scratch.served.data(),
                        scratch.rotationCos.data(), scratch.rotationSin.data(), arrays, image(out.visibility, 0),
                        image(out.blockerDistance, 0), image(out.penumbraWidth, 0), image(out.knownTaps, 0),
                        image(out.searchLevel, 0), vectors};
    // The row's tail, fewer pixels than a vector, goes through the scalar twins (the same bits).
    const auto at = [&](float* a) { return a ? a + vectors : a; };
    const LookupRow tail{row.position + 3 * vectors, row.normal + 3 * vectors, row.served + vectors,
                         row.rotationCos + vectors, row.rotationSin + vectors,
                         {at(arrays.texelX), at(arrays.texelY), at(arrays.depth), at(arrays.slopeX), at(arrays.slopeY),
                          at(arrays.tolerance), at(arrays.distance)},
                         image(out.visibility, vectors), image(out.blockerDistance, vectors),
                         image(out.penumbraWidth, vectors), image(out.knownTaps, vectors),
                         image(out.searchLevel, vectors), count - vectors};
    const auto stage = [&](LookupKernel vector, LookupKernel scalar) {
        vector(t.constants, row);
        scalar(t.constants, tail);
    };
    stage(t.reach, t.scalarReach);
    uint8_t* served = scratch.served.data();   // a local: a byte stored through the vector could alias its pointer
    for (int i = 0; i < count; ++i) {
        if (served[i] & kReachUndecided) {
            served[i] = t.reaches(g.position[k + size_t(i)], g.normal[k + size_t(i)]) ? served[i] & ~kReachUndecided : 0;
        }
    }
    stage(t.project, t.scalarProject);
    stage(t.filter, t.scalarFilter);
}

void lookUpEveryRow(const GBuffer& g, const LookupPass& pass, const LookupPass::Outputs& out) {
    tbb::parallel_for(tbb::blocked_range<int>(0, g.height), [&](const tbb::blocked_range<int>& rows) {
        LookupPass::Scratch scratch(g.width);
        for (int j = rows.begin(); j < rows.end(); ++j) {
            std::copy_n(g.hit.begin() + ptrdiff_t(g.index(0, j)), g.width, scratch.served.begin());
            pass.lookUpRow(g, j, scratch, out);
        }
    });
}

double texelsPerPixel(const DepthMap& map, const PixelRays& rays, int i, int j, const glm::dvec3& P, const glm::dvec3& N) {
    const glm::dvec2 t = texelOf(map, P);
    const glm::dvec2 dx = texelOf(map, onPlane(rays, i + 1, j, P, N)) - t;
    const glm::dvec2 dy = texelOf(map, onPlane(rays, i, j + 1, P, N)) - t;
    const double area = std::abs(dx.x * dy.y - dx.y * dy.x);
    return std::isfinite(area) ? area : 0.0;
}

double medianTexelDensity(const ShadowLookup& lookup) {
    std::vector<float> served;
    const int height = lookup.width ? int(lookup.mapIndex.size()) / lookup.width : 0;
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < lookup.width; ++i) {
            const size_t k = size_t(j) * size_t(lookup.width) + size_t(i);
            if (lookup.mapIndex[k] >= 0 && inDensitySample(i, j)) served.push_back(lookup.texelDensity[k]);
        }
    }
    if (served.empty()) return 0.0;
    std::nth_element(served.begin(), served.begin() + served.size() / 2, served.end());
    return served[served.size() / 2];
}

}  // namespace shadowlab
