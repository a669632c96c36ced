#pragma once
#include "debrisflow/dem/contact_force_k.hpp"
#include "debrisflow/dem/wall_set.hpp"
#include "debrisflow/rigid/body_model.hpp"
#include "debrisflow/rigid/body_state.hpp"
#include "debrisflow/rigid/load_recorder.hpp"
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::rigid {

// Contacts of rigid bodies with the DEM contact laws (dem::resolve_contact):
//  - smooth, geometry-exact body-wall contact: every contact vertex (Hertz radius
//    BodyState::contact_radius) and exact sphere of a body against the planes and triangles of
//    the geometric walls; one contact per feature and wall (a sphere's deepest, a vertex's
//    shallowest), so a face resting on a plane pushes at its corners whatever the SPH
//    resolution; against a face of a convex solid (a structure's box) a vertex is inside only
//    if behind all its faces and leaves by the nearest exposed one; against an open surface
//    (an STL wall) it keeps the side of a triangle it came from while within reach;
//  - distributed body-body contact between the surface sample spheres of different bodies
//    (Canelas et al. 2017: each pair of touching samples is one contact of the two bodies).
// Tangential history is kept per contact; evaluations inside a step use the history of the
// step's start plus the time elapsed, and the end-of-step evaluation commits it.
class BodyContacts {
public:
    BodyContacts(std::vector<dem::PairParams> table, int materials)
        : table_(std::move(table)), materials_(materials) {}

    // Adds contact loads; returns the largest rate (1/s^2) over the bodies of the sum over
    // their contacts of stiffness x normal compliance (1/m + (r x n).I^-1(r x n) of each side):
    // omega^2 of the stiffest contact mode, bounded above (Gershgorin).
    // Features that are not touching but will within `horizon` seconds at their approach
    // speed set imminent_dt() to 0.1 x the impact duration at that speed, so that a fast
    // approach does not enter a stiff contact with a step sized for the free flight.
    Real compute(const std::vector<BodyState>& s, const std::vector<BodyModel>& m,
                 const dem::WallSet* walls, std::vector<BodyLoads>& loads, Real elapsed,
                 bool commit, Real horizon);
    long contacts() const { return contacts_; }
    Real imminent_dt() const { return imminent_dt_; }
    // Force of the bodies on each geometric wall in the last evaluation [N].
    const std::vector<Vec3>& wall_forces() const { return wall_force_; }
    // Each contact's load on wall w (walls with record_contacts only), last evaluation.
    const std::vector<std::vector<dem::ContactLoad>>& wall_contacts() const {
        return wall_contacts_;
    }
    // Force of the bodies on each moving node of nodal walls (dem::WallSet::nodes()) [N].
    const std::vector<Vec3>& node_forces() const { return node_force_; }
    // Strongest single contact of each body in the last evaluation.
    const std::vector<StrongestContact>& strongest() const { return strongest_; }
    // Saves or restores the contact memory and the last evaluation's loads
    // (rigid/rigid_checkpoint.cpp).
    void state(checkpoint::Archive& ar);

private:
    struct Hit {
        Real delta;
        Vec3 n, point;
    };
    void add(const dem::PairParams& p, const Hit& h, const BodyState& a, const BodyState* b,
             int wall, Vec3 wall_velocity, Real r_eff, Real m_eff, BodyLoads& la, BodyLoads* lb,
             dem::ContactHistory& hist, Real elapsed);
    const dem::PairParams& pair(int a, int b) const { return table_[a * materials_ + b]; }

    std::vector<dem::PairParams> table_;
    int materials_;
    std::unordered_map<std::uint64_t, dem::ContactHistory> wall_hist_, body_hist_;
    // Outside side (+1: along the triangle's normal, -1: against) of each vertex within
    // contact reach of a triangle, by (body, vertex, primitive), from the last committed step.
    struct SideKey {
        std::uint32_t body, vertex;
        std::size_t primitive;
        bool operator==(const SideKey&) const = default;
    };
    struct SideKeyHash {
        std::size_t operator()(const SideKey& k) const {
            return (std::size_t(k.body) * 0x9E3779B97F4A7C15ull) ^
                   (std::size_t(k.vertex) * 0xC2B2AE3D27D4EB4Full) ^ (k.primitive * 0x165667B1ull);
        }
    };
    std::unordered_map<SideKey, std::int8_t, SideKeyHash> side_;
    long contacts_ = 0;
    Real max_rate_ = 0;
    const BodyState* first_ = nullptr; // bodies of the current compute(), for rate_
    std::vector<Real> rate_;           // summed contact stiffness x compliance per body [1/s^2]
    Real imminent_dt_ = 0;
    std::vector<Vec3> wall_force_, node_force_;
    std::vector<std::vector<dem::ContactLoad>> wall_contacts_;
    std::vector<StrongestContact> strongest_;
};

} // namespace debrisflow::rigid
