#pragma once
#include "debrisflow/rigid/body_state.hpp"
#include <string>
#include <vector>

namespace debrisflow::checkpoint {
class Archive;
}

namespace debrisflow::rigid {

// What touched a body hardest in a contact evaluation: the partner (a wall, by index, or
// another body) and the normal force and overlap of that single contact.
struct StrongestContact {
    int wall = -1, body = -1; // one of them >= 0 when the body touched something
    Real fn = 0, delta = 0;   // [N], [m]
    Vec3 point;               // [m]
};

// Largest fluid and contact forces on each body over the last one to two windows of `window`
// seconds, with when they acted and (for contacts) the strongest single contact, so that a
// body thrown out of the model can be reported with what threw it.
class LoadRecorder {
public:
    explicit LoadRecorder(Real window) : window_(window) {}
    void record(Real t, const std::vector<BodyLoads>& loads,
                const std::vector<StrongestContact>& strongest);
    // "over the last ... s: largest fluid force ... N at t = ... s; ..." for body b of weight
    // `weight` [N] (walls named by wall_names, bodies by body_names).
    std::string describe(std::size_t b, Real weight, const std::vector<std::string>& wall_names,
                         const std::vector<std::string>& body_names) const;

    void state(checkpoint::Archive& ar); // the two windows (rigid/rigid_checkpoint.cpp)

private:
    struct Peak {
        Real fluid = 0, t_fluid = 0;
        Real contact = 0, t_contact = 0;
        StrongestContact at_contact;
    };
    Real window_;
    Real start_ = 0;                       // start of the current window
    std::vector<Peak> current_, previous_; // per body
};

} // namespace debrisflow::rigid
