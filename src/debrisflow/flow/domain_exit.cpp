#include "debrisflow/flow/domain_exit.hpp"
#include "debrisflow/dem/dem_solver.hpp"
#include "debrisflow/exec/parallel.hpp"
#include "debrisflow/sph/sph_solver.hpp"
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace debrisflow::flow {

const std::array<const char*, 6> face_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};

long ExitTally::total_count() const {
    long n = 0;
    for (long c : count) n += c;
    return n;
}

Real ExitTally::total_mass() const {
    Real m = 0;
    for (Real c : mass) m += c;
    return m;
}

int DomainExit::face_of(Vec3 p) const {
    return faces()(p);
}

std::string DomainExit::tally_fluid(const std::vector<Leaver>& leavers, Real mass_in_set, Real t) {
    return tally("fluid particles", dim_ == 2 ? "kg/m" : "kg", fluid_, fluid_warned_, leavers,
                 mass_in_set, t);
}

std::vector<DomainExit::Leaver> DomainExit::leavers(const std::vector<int>& face,
                                                    const std::vector<Real>& mass) {
    std::vector<Leaver> out;
    for (std::size_t k = 0; k < face.size(); ++k) out.push_back({face[k], mass[k]});
    return out;
}

std::string DomainExit::tally_grains(const std::vector<Leaver>& leavers, Real mass_in_set, Real t) {
    return tally("grains", "kg", grains_, grains_warned_, leavers, mass_in_set, t);
}

std::string DomainExit::tally(const char* phase, const char* unit, ExitTally& into, bool& warned,
                              const std::vector<Leaver>& leavers, Real mass_in_set, Real t) {
    const auto before = into.count;
    const Real held = into.total_mass() + mass_in_set; // lost before + in the set
    for (const Leaver& l : leavers) {
        ++into.count[std::size_t(l.face)];
        into.mass[std::size_t(l.face)] += l.mass;
    }
    return note(phase, unit, into, before, held, warned, t);
}

std::string DomainExit::note(const char* phase, const char* unit, ExitTally& tally,
                             const std::array<long, 6>& before, Real held, bool& warned,
                             Real t) const {
    std::string out;
    for (std::size_t f = 0; f < 6; ++f)
        if (before[f] == 0 && tally.count[f] > 0)
            out += fmt::format("{}t = {:.6g} s: {} {} left the domain through its {} face: "
                               "removed (domain.exit = \"remove\"; further ones are counted in "
                               "summary.json, not logged)",
                               out.empty() ? "" : "\n", t, tally.count[f], phase, face_names[f]);
    const Real lost = tally.total_mass();
    if (!warned && held > 0 && lost > spec_.warn_fraction * held) {
        warned = true;
        out +=
            fmt::format("{}WARNING: t = {:.6g} s: the {} that left the domain ({} of them, "
                        "{:.4g} {}) exceed {:.3g} % of the mass of the {} ({:.4g} {}); check the "
                        "domain, the walls and the time step",
                        out.empty() ? "" : "\n", t, phase, tally.total_count(), lost, unit,
                        100 * spec_.warn_fraction, phase, held, unit);
    }
    return out;
}

std::string DomainExit::apply(sph::SphSolver* fluid, dem::DemSolver* grains, Real t) {
    if (!removes()) return "";
    std::string log;
    auto join = [&](const std::string& s) {
        if (!s.empty()) log += (log.empty() ? "" : "\n") + s;
    };
    auto finite = [](Vec3 p) {
        return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
    };
    if (fluid) {
        auto& s = fluid->particles();
        const Index n = s.size();
        const auto fluid_kind = std::uint8_t(particles::Kind::fluid);
        const Real any = exec::max_of(n, [&](Index i) {
            const Vec3 p{s.x[i], s.y[i], s.z[i]};
            return s.kind[i] == fluid_kind && finite(p) && face_of(p) >= 0 ? Real(1) : Real(0);
        });
        if (any > 0) {
            std::vector<std::uint8_t> keep(std::size_t(n), 1);
            std::vector<Leaver> leavers;
            Real mass_in_set = 0;
            for (Index i = 0; i < n; ++i) {
                if (s.kind[i] != fluid_kind) continue;
                mass_in_set += s.mass[i];
                const int f = faces().of_finite({s.x[i], s.y[i], s.z[i]});
                if (f < 0) continue;
                keep[std::size_t(i)] = 0;
                leavers.push_back({f, s.mass[i]});
            }
            fluid->remove_particles(keep);
            join(tally_fluid(leavers, mass_in_set, t));
        }
    }
    if (grains && grains->may_have_left()) {
        auto& g = grains->grains();
        const Index n = g.size();
        std::vector<std::uint8_t> keep(std::size_t(n), 1);
        Real mass_in_set = 0;
        bool any = false;
        std::vector<int> face(std::size_t(n), -1);
        for (Index i = 0; i < n; ++i) {
            const std::size_t k = std::size_t(i);
            mass_in_set += g.mass[k];
            face[k] = finite(g.pos[k]) ? face_of(g.pos[k]) : -1;
            if (face[k] < 0) continue;
            keep[k] = 0;
            any = true;
        }
        if (any) {
            // a clump leaves whole: its members still inside count at a face one of them crossed
            grains->expand_to_clumps(keep);
            grains->spread_clump_faces(face);
            std::vector<Leaver> leavers;
            for (Index i = 0; i < n; ++i) {
                const std::size_t k = std::size_t(i);
                // not finite: its clump goes, the health check speaks
                if (!keep[k] && face[k] >= 0) leavers.push_back({face[k], g.mass[k]});
            }
            grains->remove_grains(keep);
            join(tally_grains(leavers, mass_in_set, t));
        }
    }
    return log;
}

} // namespace debrisflow::flow
