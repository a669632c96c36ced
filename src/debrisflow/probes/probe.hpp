#pragma once
#include "debrisflow/io/case_spec.hpp"
#include "debrisflow/probes/probe_setup.hpp"
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}
namespace debrisflow::sph {
class SphSolver;
}
namespace debrisflow::dem {
class DemSolver;
}
namespace debrisflow::rigid {
class BodySolver;
}
namespace debrisflow::fem {
class FemSolver;
}
namespace debrisflow::flow {
class DomainExit;
}

namespace debrisflow::probes {

class FluidReader;
class GrainReader;

// What a probe may look at: the fluid, the grains, the rigid bodies, the FEM solids (null when
// absent) and the tally of what left the domain.
struct ProbeContext {
    const sph::SphSolver* sph = nullptr;
    dem::DemSolver* dem = nullptr;
    const rigid::BodySolver* rigid = nullptr;
    const fem::FemSolver* fem = nullptr;
    const flow::DomainExit* domain_exit = nullptr; // what left the domain
    // The fluid's point samples and reductions, where its particles are (fluid_reader.hpp).
    const FluidReader* fluid = nullptr;
    // The grains' sums, maxima and rows, where they are (grain_reader.hpp).
    GrainReader* grains = nullptr;
};

// Largest mean of the series (t_k, v_k), joined linearly, over any window [t - window, t]
// with t - window >= t_0; NaN when the series is shorter than the window.
Real peak_moving_mean(const std::vector<Real>& t, const std::vector<Real>& v, Real window);

// A measurement taken on a schedule and written to probes/<name>.csv (first column time [s]).
// Peak (largest value) and final value of every column go to summary.json. A probe type that
// a [[probe]] block can name has a type_name and reads its own keys in
// from_config(const ProbeSetup&), and is listed in probe_registry.cpp.
class Probe {
public:
    virtual ~Probe() = default;
    const std::string& name() const { return name_; }
    // Column headers with SI units, e.g. "p [Pa]".
    virtual std::vector<std::string> columns() const = 0;
    // One sample at time t (probes that integrate over the sampling interval keep state).
    virtual std::vector<Real> sample(Real t, const ProbeContext& ctx) = 0;

    Real every() const { return every_; }
    // Whether a sample reads the particle arrays on the host (ctx.sph's set, published from a
    // resident backend first); false for probes that read only a FluidReader, the bodies,
    // the grains (through ctx.grains, a GrainReader) or their own tallies.
    virtual bool reads_particles() const { return true; }
    // Opens probes/<name>.csv in `dir`; probes with field output also open their VTK series.
    void open(const std::string& dir);
    virtual void open_extra(const std::string& /*dir*/) {}
    // Called after each sample with its values (field output).
    virtual void after_sample(Real /*t*/, const std::vector<Real>& /*values*/) {}
    void record(Real t, const ProbeContext& ctx);
    // Writes the buffered rows to probes/<name>.csv (at each progress line, so that a run
    // killed outright keeps its series up to then).
    void flush() {
        if (csv_.is_open()) csv_.flush();
    }
    const std::vector<Real>& peaks() const { return peak_; }
    const std::vector<Real>& finals() const { return last_; }
    bool has_samples() const { return samples_ > 0; }
    Real peak_time(std::size_t column) const { return peak_t_[column]; }
    // Every sample taken: {time, column values...}.
    const std::vector<std::vector<Real>>& history() const { return history_; }
    // Mean of a column over samples with t0 <= t <= t1.
    Real mean(std::size_t column, Real t0, Real t1) const;
    // Largest mean of a column over any window [t - window, t] within the run (the samples
    // joined linearly): what a sensor that averages over `window` would peak at. NaN when the
    // samples are too sparse for the window (every > window / 2) or the run is shorter.
    Real peak_window_mean(std::size_t column, Real window) const;
    // Saves or restores the samples, peaks, the CSV's length and what the probe keeps between
    // samples (extra_state). A restored probe's open() cuts its CSV back to that length and
    // appends, so rows written after the checkpoint by the stopped run are replaced.
    void state(checkpoint::Archive& ar);
    // What a probe keeps between samples (previous values, accumulators, field frames).
    virtual void extra_state(checkpoint::Archive& /*ar*/) {}
    // The wall (index in the case's walls) whose grain and body contacts this probe reads one by
    // one, so that the contact loops record them; -1: none.
    virtual int contact_wall() const { return -1; }

protected:
    Probe(std::string name, Real every) : name_(std::move(name)), every_(every) {}

private:
    std::string name_;
    Real every_;
    std::ofstream csv_;
    std::vector<Real> peak_, peak_t_, last_;
    long samples_ = 0;
    std::vector<std::vector<Real>> history_;
    std::int64_t resume_bytes_ = -1; // CSV length to continue from (a restored probe)
};

} // namespace debrisflow::probes
