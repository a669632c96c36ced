#include "debrisflow/app/summary.hpp"
#include "debrisflow/io/quoted.hpp"
#include <cmath>
#include <fmt/format.h>
#include <fstream>

namespace debrisflow::app {

using io::quoted;

namespace {
std::string num(double v) {
    return std::isfinite(v) ? fmt::format("{:.9g}", v) : "null";
}
} // namespace

void write_summary(const std::string& path, const io::CaseSpec& spec, const RunReport& r,
                   const std::vector<std::unique_ptr<probes::Probe>>& probes,
                   const std::vector<probes::DesignCheck>& design) {
    std::ofstream o(path);
    const auto& res = r.result;
    const long n = r.fluid + r.boundary + r.grains;
    const double ps = r.particle_steps > 0 ? r.particle_steps : double(n) * double(res.steps);
    const double pss = res.wall_seconds > 0 ? ps / res.wall_seconds : 0;
    o << "{\n";
    o << "  \"case\": " << quoted(spec.name) << ",\n";
    o << "  \"status\": " << quoted(r.status) << ",\n";
    if (!r.message.empty()) o << "  \"message\": " << quoted(r.message) << ",\n";
    o << "  \"dimensions\": " << spec.dim << ",\n";
    o << "  \"dp\": " << num(spec.dp) << ",\n";
    o << fmt::format("  \"particles\": {{\"fluid\": {}, \"boundary\": {}, \"grains\": {}, "
                     "\"total\": {}}},\n",
                     r.fluid, r.boundary, r.grains, n);
    o << fmt::format("  \"particles_end\": {{\"fluid\": {}, \"grains\": {}}},\n", r.fluid_end,
                     r.grains_end);
    // Fluid particles and grains removed because they left the domain (domain.exit = "remove").
    auto exit_block = [&](const flow::ExitTally& e, const char* unit) {
        std::string faces;
        for (std::size_t f = 0; f < 6; ++f)
            faces += fmt::format("{}{}: {{\"count\": {}, \"mass\": {}}}", f ? ", " : "",
                                 quoted(flow::face_names[f]), e.count[f], num(e.mass[f]));
        return fmt::format(
            "{{\"count\": {}, \"mass\": {}, \"mass_unit\": \"{}\", \"faces\": {{{}}}}}",
            e.total_count(), num(e.total_mass()), unit, faces);
    };
    o << "  \"left_domain\": {\"policy\": " << quoted(spec.domain_exit.policy)
      << ", \"fluid\": " << exit_block(r.fluid_exit, spec.dim == 2 ? "kg/m" : "kg")
      << ", \"grains\": " << exit_block(r.grain_exit, "kg") << "},\n";
    o << "  \"steps\": " << res.steps << ",\n";
    o << "  \"simulated_time\": " << num(res.t) << ",\n";
    o << "  \"end_time\": " << num(spec.t_end) << ",\n";
    o << "  \"initial_dt\": " << num(r.initial_dt.dt) << ",\n";
    o << "  \"initial_dt_limiter\": " << quoted(r.initial_dt.limiter) << ",\n";
    o << "  \"wall_seconds\": " << num(res.wall_seconds) << ",\n";
    o << "  \"particle_steps_per_second\": " << num(pss) << ",\n";
    o << "  \"threads\": " << r.threads << ",\n";
    o << "  \"pair_list_builds\": " << r.pair_list_builds << ",\n";
    o << "  \"pair_list_entries\": " << r.pairs << ",\n";
    // What an impact pressure peak scales with: the water hammer rho0 c0 u of the artificial
    // sound speed (docs/validation.md, "The impact peak is acoustic").
    if (spec.sph.c0 > 0)
        o << fmt::format("  \"sph\": {{\"c0\": {}, \"rho0\": {}, \"h\": {}, \"boundary\": {}}},\n",
                         num(spec.sph.c0), num(spec.sph.rho0), num(spec.sph.h),
                         quoted(spec.sph.boundary));
    if (r.sph_bytes > 0) {
        o << fmt::format(
            "  \"sph_memory\": {{\"backend\": {}, \"pair_loop\": {}, \"bytes\": {}, "
            "\"bytes_per_particle\": {}{}}},\n",
            quoted(spec.backend), quoted(spec.backend == "host" ? spec.sph.pair_loop : "cells"),
            r.sph_bytes,
            num(r.sph_particles > 0 ? double(r.sph_bytes) / double(r.sph_particles) : 0),
            r.sph_copies_to_host >= 0
                ? fmt::format(", \"copies_to_host\": {}", r.sph_copies_to_host)
                : "");
    }
    if (r.grains > 0)
        o << fmt::format("  \"dem\": {{\"dt\": {}, \"dt_limiter\": {}, \"contacts\": {}, "
                         "\"neighbor_rebuilds\": {}}},\n",
                         num(r.dem_dt.dt), quoted(r.dem_dt.limiter), r.dem_contacts,
                         r.dem_list_builds);
    if (r.dem_bytes > 0)
        o << fmt::format("  \"dem_memory\": {{\"backend\": {}, \"bytes\": {}, "
                         "\"bytes_per_grain\": {}, \"copies_to_host\": {}, "
                         "\"copies_from_host\": {}}},\n",
                         quoted(spec.backend), r.dem_bytes,
                         num(r.grains_end > 0 ? double(r.dem_bytes) / double(r.grains_end) : 0),
                         r.dem_copies_to_host, r.dem_copies_from_host);
    if (r.bodies > 0)
        o << fmt::format("  \"rigid\": {{\"bodies\": {}, \"contacts\": {}}},\n", r.bodies,
                         r.body_contacts);
    if (r.fem_elements > 0)
        o << fmt::format(
            "  \"fem\": {{\"nodes\": {}, \"elements\": {}, \"eroded\": {}, \"dt\": {}, "
            "\"steps\": {}, \"element_steps_per_second\": {}}},\n",
            r.fem_nodes, r.fem_elements, r.fem_eroded, num(r.fem_dt), r.fem_substeps,
            num(res.wall_seconds > 0
                    ? double(r.fem_elements) * double(r.fem_substeps) / res.wall_seconds
                    : 0));
    const auto& t = res.timings;
    o << fmt::format("  \"timings\": {{\"neighbors\": {}, \"forces\": {}, \"integration\": {}, "
                     "\"output\": {}}},\n",
                     num(t.neighbors), num(t.forces), num(t.integration), num(t.output));
    bool first = true;
    for (const auto& w : spec.walls) {
        if (w.structure.empty()) continue;
        o << (first ? "  \"structures\": [" : ",") << "\n    {\"name\": " << quoted(w.name)
          << ", \"type\": " << quoted(w.structure) << ", \"boxes\": " << w.boxes.size();
        if (w.structure == "slit_dam") o << ", \"slit_density\": " << num(w.slit_density);
        o << "}";
        first = false;
    }
    if (!first) o << "\n  ],\n";
    if (!design.empty()) {
        o << "  \"design\": [";
        for (std::size_t k = 0; k < design.size(); ++k) {
            const auto& d = design[k];
            o << (k ? ",\n" : "\n") << "    {\"probe\": " << quoted(d.probe)
              << ", \"F_peak\": " << num(d.f_peak) << ", \"F_peak_time\": " << num(d.f_peak_time);
            if (d.hydro)
                o << fmt::format(", \"hydrodynamic\": {{\"rho\": {}, \"v\": {}, \"h\": {}, "
                                 "\"w\": {}, \"alpha\": {}}}",
                                 num(d.rho), num(d.v), num(d.h), num(d.w), num(d.alpha));
            if (d.hertz)
                o << fmt::format(", \"hertz\": {{\"mass\": {}, \"radius\": {}, \"v\": {}, "
                                 "\"E_star\": {}, \"F_hertz\": {}, \"K_c\": {}, "
                                 "\"F_design\": {}, \"F_bodies_peak\": {}}}",
                                 num(d.mass), num(d.radius), num(d.v_impact), num(d.e_star),
                                 num(d.f_hertz), num(d.k_c), num(d.k_c * d.f_hertz),
                                 num(d.f_bodies_peak));
            if (!d.note.empty()) o << ", \"note\": " << quoted(d.note);
            o << "}";
        }
        o << "\n  ],\n";
    }
    o << "  \"probes\": {";
    for (std::size_t k = 0; k < probes.size(); ++k) {
        const auto& p = *probes[k];
        o << (k ? ",\n" : "\n") << "    " << quoted(p.name()) << ": {";
        const auto cols = p.columns();
        for (std::size_t c = 0; c < cols.size(); ++c) {
            const bool any = p.has_samples();
            o << (c ? ", " : "") << quoted(cols[c])
              << fmt::format(": {{\"peak\": {}, \"peak_time\": {}, \"final\": {}",
                             any ? num(p.peaks()[c]) : "null", any ? num(p.peak_time(c)) : "null",
                             any ? num(p.finals()[c]) : "null");
            // the peak as sensors that average over 1, 5, 20 and 50 ms would read it
            for (const auto& [key, w] :
                 {std::pair{"peak_mean_1ms", 0.001}, std::pair{"peak_mean_5ms", 0.005},
                  std::pair{"peak_mean_20ms", 0.02}, std::pair{"peak_mean_50ms", 0.05}}) {
                o << ", \"" << key << "\": " << num(any ? p.peak_window_mean(c, Real(w)) : NAN);
            }
            o << "}";
        }
        o << "}";
    }
    o << (probes.empty() ? "}\n" : "\n  }\n");
    o << "}\n";
}

} // namespace debrisflow::app
