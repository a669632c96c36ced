#include "debrisflow/coupling/coupling.hpp"

namespace debrisflow::coupling {

const char* when_name(When w) {
    switch (w) {
    case When::force_evaluation:
        return "in the force evaluation";
    case When::fem_step_loads:
        return "once per FEM advance";
    case When::fem_loads:
        return "in the FEM force evaluation";
    case When::fem_motion:
        return "after each FEM advance";
    case When::body_motion:
        return "after each update of the bodies";
    case When::between_steps:
        return "between steps";
    }
    return "?";
}

std::string describe(const Exchange& e) {
    return e.from + " -> " + e.to + ": " + e.what + " (" + when_name(e.when) + ")";
}

} // namespace debrisflow::coupling
