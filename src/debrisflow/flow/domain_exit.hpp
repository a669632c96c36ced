#pragma once
#include "debrisflow/flow/exit_faces_k.hpp"
#include "debrisflow/io/case_spec.hpp"
#include <array>
#include <string>
#include <vector>

namespace debrisflow::dem {
class DemSolver;
}
namespace debrisflow::sph {
class SphSolver;
}

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::flow {

// The tally of one phase: count and mass [kg] (2D: kg/m) per face, in the order
// x-, x+, y-, y+, z-, z+.
struct ExitTally {
    std::array<long, 6> count{};
    std::array<Real, 6> mass{};
    long total_count() const;
    Real total_mass() const;
};

// Face names for CSV columns and summary.json.
extern const std::array<const char*, 6> face_names; // "xmin", "xmax", ...

// Removes the fluid particles and grains outside the domain (io::DomainExitSpec, policy
// "remove") and keeps the tally; with policy "stop" it does nothing and the solvers' health
// checks stop the run.
class DomainExit {
public:
    DomainExit(const io::DomainExitSpec& spec, const Domain& domain, int dim)
        : spec_(spec), domain_(domain), dim_(dim) {}

    // Removes what is outside now (either solver may be null). Returns one log line per phase
    // that just crossed the warning fraction, or per face first crossed ("" when none).
    std::string apply(sph::SphSolver* fluid, dem::DemSolver* grains, Real t);

    bool removes() const { return spec_.policy == "remove"; }
    const ExitTally& fluid() const { return fluid_; }
    const ExitTally& grains() const { return grains_; }
    void state(checkpoint::Archive& ar); // tallies and warnings given (flow/flow_state.cpp)

    // The face a finite point outside the domain crossed (index into face_names), or -1 when
    // it is inside (periodic directions and y in 2D never count).
    int face_of(Vec3 p) const;
    ExitFaces faces() const { return {domain_, dim_}; }

    // One fluid particle or grain that left: the face it crossed and its mass.
    struct Leaver {
        int face;
        Real mass;
    };
    // Counts fluid particles that left (in index order) against the fluid mass the set held
    // before they were removed; the log lines as apply's. The resident SPH loop finds and
    // removes its leavers itself and reports them here.
    std::string tally_fluid(const std::vector<Leaver>& leavers, Real mass_in_set, Real t);
    // The leavers a resident phase reports as faces and masses, paired up.
    static std::vector<Leaver> leavers(const std::vector<int>& face, const std::vector<Real>& mass);
    // The same for grains (the resident DEM loop's leavers; their masses in kg).
    std::string tally_grains(const std::vector<Leaver>& leavers, Real mass_in_set, Real t);

private:
    std::string tally(const char* phase, const char* unit, ExitTally& into, bool& warned,
                      const std::vector<Leaver>& leavers, Real mass_in_set, Real t);
    std::string note(const char* phase, const char* unit, ExitTally& tally,
                     const std::array<long, 6>& before, Real held, bool& warned, Real t) const;
    io::DomainExitSpec spec_;
    Domain domain_;
    int dim_;
    ExitTally fluid_, grains_;
    bool fluid_warned_ = false, grains_warned_ = false;
};

} // namespace debrisflow::flow
