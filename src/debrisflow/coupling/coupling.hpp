#pragma once
#include <string>
#include <vector>

// The protocol every coupling follows: what it hands from one model to another, through which
// buffer, and at which point of the step. The couplings of a case are listed in the log with
// their exchanges; the order of the phases they need is in coupling/step_order.hpp.
namespace debrisflow::coupling {

// Where in a step an exchange happens, in the order these points occur in one global step.
enum class When {
    // Inside every force evaluation, as a phase after the phases it reads (step_order.hpp).
    force_evaluation,
    // Once per FEM advance: an impulse gathered over the sub-steps of the step, divided by dt.
    fem_step_loads,
    // Inside every FEM force evaluation: added to the nodal forces (the FEM phase is last).
    fem_loads,
    // After every FEM advance and prediction: what rides on the nodes follows them.
    fem_motion,
    // After every update of the rigid bodies: what rides on them follows them.
    body_motion,
    // After the integration, before the neighbour search (particles added or removed).
    between_steps,
};
const char* when_name(When w);

// One transfer: from a model to a model, what (with its buffer), when.
struct Exchange {
    std::string from, to, what;
    When when;
};

// A coupling between two models. The object owns the exchange's buffers and does the
// transfers; exchanges() states them (the log prints them, a test checks them against the
// order of the phases).
class Coupling {
public:
    virtual ~Coupling() = default;
    virtual const char* coupling_name() const = 0;
    virtual std::vector<Exchange> exchanges() const = 0;
};

// "sph -> fem: fluid force on ... (fem loads)"
std::string describe(const Exchange& e);

} // namespace debrisflow::coupling
