#include "debrisflow/coupling/step_order.hpp"
#include <stdexcept>
#include <string>

namespace debrisflow::coupling {

const std::vector<OrderRule>& order_rules() {
    static const std::vector<OrderRule> rules = {
        {"sph", "sph-dem",
         "interpolates the fluid's pressure, velocity and density of this evaluation at the "
         "grains, and adds the grains' reaction to the fluid accelerations just computed"},
        {"dem", "sph-dem", "hands over the impulse the DEM recorded over its last advance"},
        {"sph", "rigid",
         "sums the fluid accelerations of the bodies' boundary particles into body loads"},
        {"dem", "rigid", "reads the grains' contact impulse on the bodies' contact spheres"},
        {"sph", "fem", "its load source reads the fluid force on the carried particles"},
        {"dem", "fem", "its step source reads the grains' contact impulse on the surface"},
        {"rigid", "fem", "its load source reads the bodies' contact forces on the nodes"},
    };
    return rules;
}

std::vector<time::Phase*> force_order(const std::vector<time::Phase*>& phases) {
    std::vector<time::Phase*> left;
    for (time::Phase* p : phases)
        if (p) left.push_back(p);
    // A phase is ready when no rule asks for a phase still left to come before it; the first
    // ready phase in the given order goes next (a stable topological sort).
    const auto ready = [&](const time::Phase* p) {
        for (const OrderRule& r : order_rules()) {
            if (std::string(r.after) != p->name()) continue;
            for (const time::Phase* q : left)
                if (q != p && std::string(r.before) == q->name()) return false;
        }
        return true;
    };
    std::vector<time::Phase*> out;
    while (!left.empty()) {
        std::size_t k = 0;
        while (k < left.size() && !ready(left[k])) ++k;
        if (k == left.size())
            throw std::logic_error("the phases' order rules contradict each other");
        out.push_back(left[k]);
        left.erase(left.begin() + long(k));
    }
    return out;
}

} // namespace debrisflow::coupling
