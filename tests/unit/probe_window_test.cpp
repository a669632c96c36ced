// Probe::peak_window_mean, the peak as a sensor averaging over a window reads it, against the
// closed form for a triangular pulse A max(0, 1 - |t - c| / tau): the mean over a window w <=
// 2 tau centred on the apex is A (1 - w / (4 tau)).
#include "debrisflow/probes/probe.hpp"
#include <cmath>
#include <gtest/gtest.h>

using namespace debrisflow;

namespace {
class PulseProbe : public probes::Probe {
public:
    PulseProbe() : Probe("pulse", 1e-4) {}
    std::vector<std::string> columns() const override { return {"p [Pa]"}; }
    std::vector<Real> sample(Real t, const probes::ProbeContext&) override {
        return {1000 * std::max(0.0, 1 - std::abs(t - 0.05) / 0.01)};
    }
};
} // namespace

TEST(ProbeWindow, PeakOfAWindowMeanOfATriangularPulse) {
    PulseProbe p;
    for (int k = 0; k <= 1000; ++k) p.record(k * 1e-4, {});
    EXPECT_NEAR(p.peaks()[0], 1000, 1e-9);
    for (double w : {0.001, 0.005, 0.02})
        EXPECT_NEAR(p.peak_window_mean(0, w), 1000 * (1 - w / 0.04), 1e-6) << "window " << w;
    // too sparse for the window: not reported
    EXPECT_TRUE(std::isnan(p.peak_window_mean(0, 1e-4)));
    // longer than the run: not reported
    EXPECT_TRUE(std::isnan(p.peak_window_mean(0, 0.2)));
}
