#pragma once
#include "debrisflow/rigid/body_state.hpp"
#include <string>
#include <vector>

namespace debrisflow::rigid {

enum class JointType { hinge, ball, fixed, spring };

// A constraint between body a and body b (b = -1: the ground). Anchors and axes are stored
// in each body's principal frame (for the ground: world coordinates).
struct Joint {
    std::string name;
    JointType type = JointType::ball;
    int a = -1, b = -1;
    Vec3 anchor_a, anchor_b; // joint point (spring: its two ends)
    Vec3 axis_a, axis_b;     // hinge axis
    Quat rel0;               // fixed: orientation of b relative to a at t = 0 (qa* qb)
    Real stiffness = 0, damping = 0, rest_length = 0; // spring [N/m], [N s/m], [m]
    Vec3 impulse; // last constraint impulse on a per step, divided by dt [N]
};

// Joints between rigid bodies. Hinge, ball and fixed joints are velocity constraints solved
// by sequential impulses (projected Gauss-Seidel, as the DEM/multibody engines of the
// container paper do) with Baumgarte feedback of the position error (Baumgarte 1972): after
// every velocity update, C' = -beta C / dt at each joint. Springs are forces:
// F_a = (k (L - L0) + c dL/dt) u, u the unit vector from a's anchor to b's.
class JointSet {
public:
    std::vector<Joint>& joints() { return joints_; }
    const std::vector<Joint>& joints() const { return joints_; }
    bool empty() const { return joints_.empty(); }
    bool involves(int body) const; // body is one end of a joint

    // Adds spring-damper forces and torques to the bodies' joint loads.
    void add_spring_loads(const std::vector<BodyState>& s, std::vector<BodyLoads>& loads) const;
    // Projects body velocities onto the constraints (dt: the step the position error is fed
    // back over).
    void project(std::vector<BodyState>& s, Real dt, int iterations, Real beta);
    // Stable step of the springs: 0.1 x the shortest undamped period.
    Real stable_dt(const std::vector<BodyState>& s) const;

private:
    std::vector<Joint> joints_;
};

// Zeroes locked velocity components (translation and world rotation axes).
void apply_locks(BodyState& b);

} // namespace debrisflow::rigid
