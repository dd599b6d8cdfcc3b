// The split-sum scale and bias (shading/environment/split_sum_table.h) against brute force:
// the GGX BRDF written here from its textbook parts (D of Walter et al., Smith's
// height-correlated G2 through Lambda, Schlick's F), integrated over the hemisphere of l on
// a fine (theta, phi) grid: independent of the table's half-vector quadrature and of
// microfacet_ggx.h's algebra.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "raster/portable_constants.h"
#include "raster/thread_count.h"
#include "shading/environment/split_sum_table.h"

using namespace shadowlab;

namespace {

double lambda(double cosTheta, double alpha) {
    const double tan2 = (1.0 - cosTheta * cosTheta) / (cosTheta * cosTheta);
    return 0.5 * (-1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}

// (A, B): integral of f / F (n . l) dl split by (1 - v . h)^5, on a midpoint grid over the
// half of the hemisphere with y > 0 (f is symmetric about the plane of n and v), fine in theta
// for the sharp rise of f (n . l) above the horizon under a grazing view, and in phi ever finer
// towards pi (phi = pi (1 - (1 - t)^2), uniform in t): there a grazing view's mirror direction
// nearly cancels v, so h = normalize(l + v) turns fast with l and D(h) is a narrow peak in l.
glm::dvec2 bruteForce(double cosV, double alpha) {
    constexpr int kTheta = 4096, kPhi = 1024;
    const glm::dvec3 n(0, 0, 1), v(std::sqrt(1.0 - cosV * cosV), 0.0, cosV);
    glm::dvec2 sum(0.0);
    for (int a = 0; a < kTheta; ++a) {
        const double theta = 0.5 * kPi * (a + 0.5) / kTheta;
        for (int b = 0; b < kPhi; ++b) {
            const double t = (b + 0.5) / kPhi, phi = kPi * (1.0 - (1.0 - t) * (1.0 - t)), dPhi = 2.0 * kPi * (1.0 - t);
            const glm::dvec3 l(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
            const glm::dvec3 h = glm::normalize(l + v);
            const double cosH = glm::dot(n, h), cosL = l.z, cosVH = glm::dot(v, h);
            const double a2 = alpha * alpha, d = cosH * cosH * (a2 - 1.0) + 1.0;
            const double D = a2 / (kPi * d * d);
            const double G2 = 1.0 / (1.0 + lambda(cosL, alpha) + lambda(cosV, alpha));
            const double fOverF = D * G2 / (4.0 * cosL * cosV);
            const double w = std::pow(1.0 - cosVH, 5.0);
            sum += fOverF * cosL * std::sin(theta) * dPhi * glm::dvec2(1.0 - w, w);
        }
    }
    return sum * (kPi / (double(kTheta) * kPhi));   // twice the half's integral
}

}  // namespace

TEST_CASE("split sum: the table's scale and bias are the GGX albedo's, against brute force over the hemisphere") {
    const SplitSumTable table = buildSplitSumTable(32);
    double worstAtCentres = 0.0, worstBetween = 0.0;
    for (double cosV : {0.015625, 0.203125, 0.984375, 0.1, 0.6}) {
        for (double alpha : {0.078125, 0.515625, 0.984375, 0.13}) {
            const bool atCentre = std::fmod(cosV * 64.0, 2.0) == 1.0 && std::fmod(alpha * 64.0, 2.0) == 1.0;
            const glm::dvec2 expected = bruteForce(cosV, alpha), got = lookupSplitSum(table, cosV, alpha);
            const double error = std::max(std::abs(got.x - expected.x), std::abs(got.y - expected.y));
            INFO("cos v " << cosV << ", alpha " << alpha << ": A " << got.x << " (brute force " << expected.x << "), B "
                          << got.y << " (" << expected.y << ")");
            CHECK(error < (atCentre ? 5e-4 : 4e-3));
            (atCentre ? worstAtCentres : worstBetween) = std::max(atCentre ? worstAtCentres : worstBetween, error);
        }
    }
    MESSAGE("worst |error| in A or B: " << worstAtCentres << " at cell centres, " << worstBetween << " between them");
}

TEST_CASE("split sum: the albedo A + B of a Fresnel-one surface is at most 1, and away from grazing falls with roughness and nears 1 for a smooth one") {
    const SplitSumTable table = buildSplitSumTable(32);
    for (int i = 0; i < table.size; ++i) {
        double previous = 2.0;
        for (int j = 0; j < table.size; ++j) {
            const double a = table.scale[table.index(i, j)], b = table.bias[table.index(i, j)];
            CAPTURE(i);
            CAPTURE(j);
            CHECK(a >= 0.0);
            CHECK(b >= 0.0);
            CHECK(a + b <= 1.0 + 1e-4);
            // Away from grazing, rougher loses more; under a grazing view Smith's masking of a
            // smooth surface (alpha tan theta_v near 1) outweighs that, so not there.
            if (i >= table.size / 4) CHECK(a + b <= previous + 1e-6);
            previous = a + b;
        }
        // alpha = 1/64: a near mirror loses almost nothing between microfacets unless grazing.
        if (i >= table.size / 4) CHECK(table.scale[table.index(i, 0)] + table.bias[table.index(i, 0)] > 0.98);
    }
    // A normal view of a mirror sees F0 alone: B = (1 - 1)^5 = 0 there, and grows towards grazing.
    CHECK(table.bias[table.index(table.size - 1, 0)] < 1e-4);
    CHECK(table.bias[table.index(0, 0)] > 0.5 * table.scale[table.index(0, 0)]);
}

TEST_CASE("split sum: the same bits on 1 and 2 threads, clamped lookups, and a refused size") {
    const SplitSumTable one = withThreads(1, [] { return buildSplitSumTable(16); });
    const SplitSumTable two = withThreads(2, [] { return buildSplitSumTable(16); });
    CHECK(one.scale == two.scale);
    CHECK(one.bias == two.bias);
    // Outside the cell centres, the outermost entries; a NaN takes the first cell.
    CHECK(lookupSplitSum(one, 0.0, 2.0) == glm::dvec2(one.scale[one.index(0, 15)], one.bias[one.index(0, 15)]));
    CHECK(lookupSplitSum(one, std::numeric_limits<double>::quiet_NaN(), 0.0) ==
          glm::dvec2(one.scale[one.index(0, 0)], one.bias[one.index(0, 0)]));
    CHECK_THROWS_AS(buildSplitSumTable(1), std::invalid_argument);
    CHECK_THROWS_AS(buildSplitSumTable(4096), std::invalid_argument);
}
