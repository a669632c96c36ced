#include "debrisflow/probes/hazard_map.hpp"
#include "debrisflow/checkpoint/archive.hpp"
#include "debrisflow/probes/fluid_reader.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <fstream>
#include <limits>

namespace debrisflow::probes {

std::unique_ptr<Probe> HazardMapProbe::from_config(const ProbeSetup& s) {
    s.require(!s.c.fluids.empty(), "a fluid");
    // A plan grid over [min, max] (2D: along x); the columns count fluid between min.z and
    // max.z; depths from `bed` (default min.z).
    const auto [lo, hi] = s.box(0, 1);
    const Real bed = s.t.real("bed", lo.z);
    const auto n = s.t.reals("cells");
    const std::size_t plan = s.c.dim == 3 ? 2 : 1;
    if (n.size() != plan || std::any_of(n.begin(), n.end(), [](Real v) {
            return !(v >= 1 && v <= 10000 && v == std::floor(v));
        }))
        s.t.fail("cells", s.c.dim == 3 ? "expected [n_x, n_y], whole numbers from 1 to 10000"
                                       : "expected [n_x], a whole number from 1 to 10000");
    return std::make_unique<HazardMapProbe>(s.name(), s.every(), lo, hi, int(n[0]),
                                            s.c.dim == 3 ? int(n[1]) : 1, bed, s.c);
}

HazardMapProbe::HazardMapProbe(std::string name, Real every, Vec3 lo, Vec3 hi, int nx, int ny,
                               Real bed, const io::CaseSpec& c)
    : Probe(std::move(name), every), lo_(lo), hi_(hi), nx_(nx), ny_(c.dim == 3 ? ny : 1),
      dim_(c.dim), bed_(bed), half_dp_(Real(0.5) * c.dp),
      h_max_(std::size_t(nx_) * std::size_t(ny_), 0), v_max_(h_max_), f_max_(h_max_) {}

std::vector<Real> HazardMapProbe::sample(Real, const ProbeContext& ctx) {
    const std::size_t n = h_max_.size();
    std::vector<Real> top(n, -std::numeric_limits<Real>::max()), mass(n, 0), mrho(n, 0);
    std::vector<Vec3> mom(n);
    const Real dx = (hi_.x - lo_.x) / nx_, dy = (hi_.y - lo_.y) / ny_;
    // the fluid over the plan box (its rows, in the order of their ids)
    for (const ParticleRow& r : ctx.fluid->rows(RowSelection::fluid_in(lo_, hi_, dim_ == 3))) {
        const Real x = r.x.x, y = r.x.y, z = r.x.z;
        if (x < lo_.x || x >= hi_.x || z < lo_.z || z > hi_.z) continue;
        if (dim_ == 3 && (y < lo_.y || y >= hi_.y)) continue;
        const int cx = std::min(nx_ - 1, int((x - lo_.x) / dx));
        const int cy = dim_ == 3 ? std::min(ny_ - 1, int((y - lo_.y) / dy)) : 0;
        const std::size_t k = std::size_t(cx) + std::size_t(nx_) * std::size_t(cy);
        top[k] = std::max(top[k], z + half_dp_);
        mass[k] += r.mass;
        mrho[k] += r.mass * r.rho;
        mom[k] += r.mass * Vec3{r.v.x, dim_ == 3 ? r.v.y : Real(0), 0};
    }
    Real h_all = 0, v_all = 0, f_all = 0;
    for (std::size_t k = 0; k < n; ++k) {
        if (!(mass[k] > 0)) continue;
        const Real h = std::max(Real(0), top[k] - bed_);
        const Real v = norm(mom[k]) / mass[k];
        const Real flux = mrho[k] / mass[k] * h * v * v;
        h_max_[k] = std::max(h_max_[k], h);
        v_max_[k] = std::max(v_max_[k], v);
        f_max_[k] = std::max(f_max_[k], flux);
        h_all = std::max(h_all, h), v_all = std::max(v_all, v), f_all = std::max(f_all, flux);
    }
    return {h_all, v_all, f_all};
}

void HazardMapProbe::after_sample(Real, const std::vector<Real>&) {
    if (dir_.empty()) return;
    const Real dx = (hi_.x - lo_.x) / nx_, dy = dim_ == 3 ? (hi_.y - lo_.y) / ny_ : Real(1);
    const Real y0 = dim_ == 3 ? lo_.y : Real(0);
    std::ofstream csv(dir_ + "/" + name() + "_map.csv");
    csv << "x [m],y [m],h_max [m],v_max [m/s],momentum_flux_max [N/m]\n";
    for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) {
            const std::size_t k = std::size_t(i) + std::size_t(nx_) * std::size_t(j);
            csv << fmt::format("{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", lo_.x + (i + 0.5) * dx,
                               y0 + (j + 0.5) * dy, h_max_[k], v_max_[k], f_max_[k]);
        }
    std::ofstream vti(dir_ + "/" + name() + ".vti");
    vti << "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" "
           "byte_order=\"LittleEndian\">\n"
        << fmt::format("<ImageData WholeExtent=\"0 {0} 0 {1} 0 0\" Origin=\"{2:.9g} {3:.9g} "
                       "{4:.9g}\" Spacing=\"{5:.9g} {6:.9g} 1\">\n<Piece Extent=\"0 {0} 0 {1} "
                       "0 0\">\n<CellData Scalars=\"h_max\">\n",
                       nx_, ny_, lo_.x, y0, bed_, dx, dy);
    auto array = [&](const char* name, const std::vector<Real>& v) {
        vti << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
        for (Real x : v) vti << fmt::format("{:.9g} ", x);
        vti << "\n</DataArray>\n";
    };
    array("h_max", h_max_);
    array("v_max", v_max_);
    array("momentum_flux_max", f_max_);
    vti << "</CellData>\n</Piece>\n</ImageData>\n</VTKFile>\n";
}

void HazardMapProbe::extra_state(checkpoint::Archive& ar) {
    ar(h_max_, v_max_, f_max_);
}

} // namespace debrisflow::probes
