// multi-sample (Heckbert and Herf 1997) converges to the exact soft reference as the
// number of light points grows.
#include <doctest/doctest.h>

#include "tests/shadows/soft_test_support.h"

using namespace shadowlab;
using namespace shadowlab::test;

TEST_CASE("multi-sample: RMS against the soft reference falls with N and is small at N = 1024") {
    // Reduced size (320x200 pixels, 512^2 maps) so that 1024 maps take seconds, not minutes.
    const SoftScene s(smallScene("sphere-box", 320, 200));
    double previous = 1.0;
    for (int n : {4, 16, 64}) {
        const double rms = s.rms(s.run("multi-sample", {{"samples", std::to_string(n)}, {"resolution", "512"}}).visibility);
        MESSAGE("N = " << n << ": RMS " << rms);
        CHECK(rms < previous);
        previous = rms;
    }
    // The bound at N = 1024: both sides estimate the same visible fraction from 1024
    // stratified points, so what remains is (a) their sampling error, at most
    // sqrt(p (1 - p) / 1024) <= 0.016 per penumbra pixel even without stratification's gain,
    // and penumbrae cover under 10% of the hit pixels here, so under 0.005 in RMS; and (b)
    // each hard map's edge displaced by up to about a texel: a 512 map spans ~25 m here,
    // ~5 cm per texel, against penumbrae 10 to 40 cm wide, so V errs by up to ~0.1 over a
    // band one texel wide along each penumbra (a few % of the hit pixels): ~0.01 in RMS.
    // Together 0.015.
    const double rms = s.rms(s.run("multi-sample", {{"samples", "1024"}, {"resolution", "512"}}).visibility);
    MESSAGE("N = 1024: RMS " << rms);
    CHECK(rms < previous);
    CHECK(rms < 0.015);
}
