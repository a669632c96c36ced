#pragma once
#include "debrisflow/probes/probe.hpp"
#include <string>
#include <vector>

namespace debrisflow::probes {

// Flow-intensity map, as hazard practitioners draw it (the maxima over time of depth h, speed v
// and momentum flux rho h v^2 of a flood or debris flow): a plan grid of cells over
// [min, max] (2D: cells along x, per metre of width). Per cell and sample, over the fluid
// particles in the cell's column between min.z and max.z:
//   h = highest particle top (z + dp/2) - bed, v = |sum m v_plan| / sum m (depth-averaged),
//   rho h v^2 with rho = sum m rho / sum m, the column's mean density.
// Each cell keeps its maximum of each over the samples; probes/<name>_map.csv and
// probes/<name>.vti (VTK image, cell data) are rewritten at every sample, so that a stopped
// run leaves the map so far. The CSV series holds the largest of each over the cells.
class HazardMapProbe : public Probe {
public:
    static constexpr std::string_view type_name = "hazard_map";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s); // keys: min, max, cells, bed
    // nx x ny cells over [lo, hi] (2D: ny = 1).
    HazardMapProbe(std::string name, Real every, Vec3 lo, Vec3 hi, int nx, int ny, Real bed,
                   const io::CaseSpec& c);
    std::vector<std::string> columns() const override {
        return {"h_max [m]", "v_max [m/s]", "momentum_flux_max [N/m]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext& ctx) override;
    bool reads_particles() const override { return false; } // the plan box's rows, ctx.fluid
    void open_extra(const std::string& dir) override { dir_ = dir; }
    void after_sample(Real t, const std::vector<Real>& values) override;
    void extra_state(checkpoint::Archive& ar) override;

    // The running maxima per cell, cell (i, j) at i + nx j.
    const std::vector<Real>& depth_max() const { return h_max_; }
    const std::vector<Real>& speed_max() const { return v_max_; }
    const std::vector<Real>& flux_max() const { return f_max_; }

private:
    Vec3 lo_, hi_;
    int nx_, ny_, dim_;
    Real bed_, half_dp_;
    std::string dir_;
    std::vector<Real> h_max_, v_max_, f_max_;
};

} // namespace debrisflow::probes
