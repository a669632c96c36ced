#include "debrisflow/probes/probe.hpp"
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/core/error.hpp"
#include "debrisflow/probes/body_probe.hpp"
#include "debrisflow/probes/dem_probes.hpp"
#include "debrisflow/probes/fem_probes.hpp"
#include "debrisflow/probes/flow_instruments.hpp"
#include "debrisflow/probes/flow_probes.hpp"
#include "debrisflow/probes/hazard_map.hpp"
#include "debrisflow/probes/pressure_map.hpp"
#include "debrisflow/probes/sph_probes.hpp"
#include "debrisflow/probes/wall_force_probe.hpp"
#include <filesystem>
#include <fmt/format.h>
#include <limits>

namespace debrisflow::probes {

void Probe::open(const std::string& dir) {
    std::filesystem::create_directories(dir);
    const std::string path = dir + "/" + name_ + ".csv";
    if (resume_bytes_ >= 0) {
        std::error_code ec;
        const auto size = std::filesystem::file_size(path, ec);
        if (ec || size < std::uintmax_t(resume_bytes_))
            throw checkpoint::CheckpointError(fmt::format(
                "{} holds {} bytes, fewer than the {} the checkpoint wrote: the output folder "
                "does not belong to this checkpoint",
                path, ec ? 0 : size, resume_bytes_));
        std::filesystem::resize_file(path, std::uintmax_t(resume_bytes_));
        // in | out keeps the content; at its end, tellp() gives the length a later checkpoint
        // records even before this run writes a row
        csv_.open(path, std::ios::in | std::ios::out);
        csv_.seekp(0, std::ios::end);
        if (!csv_) throw InputError("cannot write probe file " + path);
    } else {
        csv_.open(path);
        if (!csv_) throw InputError("cannot write probe file " + path);
        csv_ << "time [s]";
        for (const auto& c : columns()) csv_ << "," << c;
        csv_ << "\n";
    }
    open_extra(dir);
}

void Probe::record(Real t, const ProbeContext& ctx) {
    const auto v = sample(t, ctx);
    after_sample(t, v);
    if (peak_.empty()) {
        peak_ = v;
        peak_t_.assign(v.size(), t);
    }
    for (std::size_t k = 0; k < v.size(); ++k)
        if (v[k] > peak_[k]) {
            peak_[k] = v[k];
            peak_t_[k] = t;
        }
    last_ = v;
    ++samples_;
    history_.push_back({t});
    history_.back().insert(history_.back().end(), v.begin(), v.end());
    if (csv_) {
        csv_ << fmt::format("{:.9g}", t);
        for (Real x : v) csv_ << fmt::format(",{:.9g}", x);
        csv_ << "\n";
    }
}

void Probe::state(checkpoint::Archive& ar) {
    ar.section("probe " + name_);
    std::int64_t bytes = -1;
    if (!ar.is_loading() && csv_.is_open()) {
        csv_.flush();
        bytes = std::int64_t(csv_.tellp());
    }
    ar(history_, peak_, peak_t_, last_, samples_, bytes);
    if (ar.is_loading()) resume_bytes_ = bytes;
    extra_state(ar);
}

Real Probe::mean(std::size_t column, Real t0, Real t1) const {
    Real sum = 0;
    long n = 0;
    for (const auto& row : history_)
        if (row[0] >= t0 && row[0] <= t1) {
            sum += row[column + 1];
            ++n;
        }
    return n ? sum / Real(n) : std::numeric_limits<Real>::quiet_NaN();
}

Real peak_moving_mean(const std::vector<Real>& t, const std::vector<Real>& v, Real window) {
    Real best = std::numeric_limits<Real>::quiet_NaN();
    if (t.size() < 2) return best;
    // integral from the first sample by the trapezoid rule, at every sample
    std::vector<Real> integral(t.size(), 0);
    for (std::size_t k = 1; k < t.size(); ++k)
        integral[k] = integral[k - 1] + Real(0.5) * (t[k] - t[k - 1]) * (v[k] + v[k - 1]);
    // the integral at x, the samples joined linearly; hint: a sample at or after x
    auto integral_at = [&](Real x, std::size_t hint) {
        while (hint > 0 && t[hint] > x) --hint;
        const std::size_t a = hint, b = std::min(hint + 1, t.size() - 1);
        if (b == a || t[b] == t[a]) return integral[a];
        const Real vx = v[a] + (x - t[a]) / (t[b] - t[a]) * (v[b] - v[a]);
        return integral[a] + Real(0.5) * (x - t[a]) * (v[a] + vx);
    };
    for (std::size_t k = 1; k < t.size(); ++k) {
        if (t[k] - window < t[0] - Real(1e-12)) continue;
        const Real m = (integral[k] - integral_at(t[k] - window, k)) / window;
        if (!(m <= best)) best = m;
    }
    return best;
}

Real Probe::peak_window_mean(std::size_t column, Real window) const {
    if (every_ > Real(0.5) * window) return std::numeric_limits<Real>::quiet_NaN();
    std::vector<Real> t, v;
    for (const auto& row : history_) {
        t.push_back(row[0]);
        v.push_back(row[column + 1]);
    }
    return peak_moving_mean(t, v, window);
}

std::unique_ptr<Probe> make_probe(const io::ProbeSpec& s, const io::CaseSpec& c) {
    if (s.type == "pressure") return std::make_unique<PressureProbe>(s);
    if (s.type == "velocity") return std::make_unique<VelocityProbe>(s);
    if (s.type == "gauge") return std::make_unique<GaugeProbe>(s, c);
    if (s.type == "front") return std::make_unique<FrontProbe>(s);
    if (s.type == "section") return std::make_unique<SectionProbe>(s, c);
    if (s.type == "kinetic_energy") return std::make_unique<KineticEnergyProbe>(s);
    if (s.type == "mass_flux") return std::make_unique<MassFluxProbe>(s, c);
    if (s.type == "body") return std::make_unique<BodyProbe>(s, c);
    if (s.type == "fem_displacement") return std::make_unique<FemDisplacementProbe>(s, c);
    if (s.type == "fem_force") return std::make_unique<FemForceProbe>(s, c);
    if (s.type == "fem_face_load") return std::make_unique<FemFaceLoadProbe>(s, c);
    if (s.type == "discharge") return std::make_unique<DischargeProbe>(s, c);
    if (s.type == "trapping") return std::make_unique<TrappingProbe>(s, c);
    if (s.type == "deposit") return std::make_unique<DepositProbe>(s, c);
    if (s.type == "flow_section") return std::make_unique<FlowSectionProbe>(s, c);
    if (s.type == "domain_exit") return std::make_unique<DomainExitProbe>(s, c.dim == 2);
    if (s.type == "hazard_map") return std::make_unique<HazardMapProbe>(s, c);
    for (std::size_t w = 0; w < c.walls.size(); ++w) {
        if (c.walls[w].name != s.wall) continue;
        if (s.type == "runup") return std::make_unique<RunupProbe>(s, int(w));
        if (s.type == "fluid_runup") return std::make_unique<FluidRunupProbe>(s, c.walls[w], c);
        if (s.type == "pressure_map")
            return std::make_unique<PressureMapProbe>(s, int(w), c.walls[w], c);
        return std::make_unique<WallForceProbe>(s, int(w), c);
    }
    throw InputError("probe '" + s.name + "': unknown wall '" + s.wall + "'");
}

} // namespace debrisflow::probes
