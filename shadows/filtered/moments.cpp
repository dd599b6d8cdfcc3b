#include "shadows/filtered/moments.h"

#include <stdexcept>

namespace shadowlab {
namespace {

const MomentModel& model(MomentKind kind) {
    switch (kind) {
        case MomentKind::Variance: return kVarianceMoments;
        case MomentKind::Exponential: return kExponentialMoments;
        case MomentKind::ExponentialVariance: return kExponentialVarianceMoments;
        case MomentKind::Hamburger4: return kHamburgerMoments;
    }
    throw std::logic_error("unknown moment kind");
}

}  // namespace

const char* momentKindName(MomentKind kind) { return model(kind).technique; }

const char* momentKindDescription(MomentKind kind) { return model(kind).description; }

int momentCount(MomentKind kind) { return model(kind).count; }

const SettingsTable<MomentSettings>& momentSettingsTable(MomentKind kind) { return model(kind).settings(); }

void momentsOf(const MomentSettings& s, double z, double* out) { momentsOfRun(s, &z, 1, out, raster::SimdLevel::Scalar); }

void momentsOfRun(const MomentSettings& s, const double* z, size_t count, double* out, raster::SimdLevel simd) {
    model(s.kind).moments(s, z, count, out, simd);
}

double momentVisibility(const MomentSettings& s, const double* m, double t) {
    double v;
    momentVisibilityRun(s, m, &t, 1, &v, raster::SimdLevel::Scalar);
    return v;
}

void momentVisibilityRun(const MomentSettings& s, const double* m, const double* t, size_t count, double* out,
                         raster::SimdLevel simd) {
    model(s.kind).visibility(s, m, t, count, out, simd);
}

double momentDynamicRange(const MomentSettings& s) { return model(s.kind).dynamicRange(s); }

}  // namespace shadowlab
