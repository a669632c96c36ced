#pragma once
#include "debrisflow/time/phase.hpp"
#include <vector>

// The order of the phases in a step, stated once. The Integrator visits its phases in the
// order they were added, in every predictor, force evaluation and corrector; couplings that
// read what another phase computed in the same evaluation must come after it.
namespace debrisflow::coupling {

// `before` must be evaluated before `after` when both are present, because `why`.
struct OrderRule {
    const char* before;
    const char* after;
    const char* why;
};

// Every ordering constraint between the phases (by Phase::name()).
const std::vector<OrderRule>& order_rules();

// The given phases (null entries skipped) sorted so that every rule holds; phases no rule
// relates keep their given order. Throws std::logic_error when the rules cannot all hold.
std::vector<time::Phase*> force_order(const std::vector<time::Phase*>& phases);

} // namespace debrisflow::coupling
