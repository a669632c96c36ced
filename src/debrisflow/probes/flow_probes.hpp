#pragma once
#include "debrisflow/flow/domain_exit.hpp"
#include "debrisflow/flow/fluid_inlet.hpp"
#include "debrisflow/flow/grain_feed.hpp"
#include "debrisflow/flow/outlet.hpp"
#include "debrisflow/probes/probe.hpp"

namespace debrisflow::probes {

// probes/<inlet>.csv: the imposed discharge and what has entered.
class InletProbe : public Probe {
public:
    // per_metre: a 2D case (quantities per metre of width, "/m" in the headers).
    InletProbe(const flow::FluidInlet& inlet, Real every, bool per_metre)
        : Probe(inlet.name(), every), inlet_(inlet), unit_(per_metre ? "/m" : "") {}
    std::vector<std::string> columns() const override {
        return {"Q [m3/s" + unit_ + "]", "U [m/s]", "mass_in [kg" + unit_ + "]",
                "volume_in [m3" + unit_ + "]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext&) override {
        return {inlet_.discharge(t), inlet_.velocity(t), inlet_.mass_in(), inlet_.volume_in()};
    }
    bool reads_particles() const override { return false; } // its own tallies

private:
    const flow::FluidInlet& inlet_;
    std::string unit_;
};

// probes/<outlet>.csv: cumulative mass and volume removed by phase, and the mean rates over the
// sampling interval (what left per second).
class OutletProbe : public Probe {
public:
    // per_metre: a 2D case; fluid columns are per metre of width, grains (discs of the case's
    // thickness) stay in kg. bodies: the case has rigid bodies (body mass and count columns).
    OutletProbe(const flow::Outlet& outlet, Real every, bool per_metre, bool bodies)
        : Probe(outlet.name(), every), outlet_(outlet), unit_(per_metre ? "/m" : ""),
          bodies_(bodies) {}
    std::vector<std::string> columns() const override {
        std::vector<std::string> c{"fluid_mass [kg" + unit_ + "]",
                                   "fluid_volume [m3" + unit_ + "]",
                                   "grain_mass [kg]",
                                   "grain_volume [m3]",
                                   "fluid_rate [kg/s" + unit_ + "]",
                                   "grain_rate [kg/s]"};
        if (bodies_) c.insert(c.end(), {"body_mass [kg" + unit_ + "]", "bodies [-]"});
        return c;
    }
    std::vector<Real> sample(Real t, const ProbeContext&) override {
        const Real dt = t - t_last_;
        const Real qf = dt > 0 ? (outlet_.fluid_mass() - fluid_last_) / dt : 0;
        const Real qg = dt > 0 ? (outlet_.grain_mass() - grain_last_) / dt : 0;
        t_last_ = t, fluid_last_ = outlet_.fluid_mass(), grain_last_ = outlet_.grain_mass();
        std::vector<Real> v{outlet_.fluid_mass(),
                            outlet_.fluid_volume(),
                            outlet_.grain_mass(),
                            outlet_.grain_volume(),
                            qf,
                            qg};
        if (bodies_) v.insert(v.end(), {outlet_.body_mass(), Real(outlet_.bodies_removed())});
        return v;
    }
    bool reads_particles() const override { return false; } // its own tallies
    void extra_state(checkpoint::Archive& ar) override;

private:
    const flow::Outlet& outlet_;
    std::string unit_;
    bool bodies_;
    Real t_last_ = 0, fluid_last_ = 0, grain_last_ = 0;
};

// probes/<feed>.csv: the target solid discharge, what has been released and what is owed (a
// growing debt means the release region is full: the feed is choked).
class FeedProbe : public Probe {
public:
    // pieces: "grains" or "rocks" (the count column).
    FeedProbe(const flow::SolidFeed& feed, Real every, std::string pieces)
        : Probe(feed.name(), every), feed_(feed), pieces_(std::move(pieces)) {}
    std::vector<std::string> columns() const override {
        return {"Qs [m3/s]", "volume_in [m3]", "mass_in [kg]", pieces_ + "_in [-]", "owed [m3]"};
    }
    std::vector<Real> sample(Real t, const ProbeContext&) override {
        return {feed_.discharge(t), feed_.volume_in(), feed_.mass_in(), Real(feed_.pieces_in()),
                feed_.owed()};
    }
    bool reads_particles() const override { return false; } // its own tallies

private:
    const flow::SolidFeed& feed_;
    std::string pieces_;
};

// probes/<name>.csv of a `domain_exit` probe: what has left the domain and been removed
// (domain.exit = "remove") so far, by phase: count and mass, then the count through each face.
class DomainExitProbe : public Probe {
public:
    static constexpr std::string_view type_name = "domain_exit";
    static std::unique_ptr<Probe> from_config(const ProbeSetup& s) { // no keys
        if (s.c.domain_exit.policy != "remove")
            s.t.fail("type", "a domain_exit probe counts what domain.exit = \"remove\" removes; "
                             "domain.exit is \"stop\"");
        return std::make_unique<DomainExitProbe>(s.name(), s.every(), s.c.dim == 2);
    }
    DomainExitProbe(std::string name, Real every, bool per_metre)
        : Probe(std::move(name), every), unit_(per_metre ? "/m" : "") {}
    std::vector<std::string> columns() const override {
        std::vector<std::string> c = {"fluid_count [-]", "fluid_mass [kg" + unit_ + "]",
                                      "grain_count [-]", "grain_mass [kg]"};
        for (const char* phase : {"fluid", "grain"})
            for (const char* face : flow::face_names)
                c.push_back(std::string(phase) + "_" + face + " [-]");
        return c;
    }
    std::vector<Real> sample(Real, const ProbeContext& ctx) override {
        flow::ExitTally none;
        const auto& f = ctx.domain_exit ? ctx.domain_exit->fluid() : none;
        const auto& g = ctx.domain_exit ? ctx.domain_exit->grains() : none;
        std::vector<Real> v = {Real(f.total_count()), f.total_mass(), Real(g.total_count()),
                               g.total_mass()};
        for (const auto* t : {&f, &g})
            for (long n : t->count) v.push_back(Real(n));
        return v;
    }
    bool reads_particles() const override { return false; } // the domain exit's tally

private:
    std::string unit_;
};

} // namespace debrisflow::probes
