#include "debrisflow/rigid/joints.hpp"
#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace debrisflow::rigid {

bool JointSet::involves(int body) const {
    for (const auto& j : joints_)
        if (j.a == body || j.b == body) return true;
    return false;
}

namespace {

using Mat3 = Eigen::Matrix3d;
using V3 = Eigen::Vector3d;
V3 ev(Vec3 v) {
    return {v.x, v.y, v.z};
}
Vec3 vec(const V3& v) {
    return {v.x(), v.y(), v.z()};
}
Mat3 skew(const V3& r) {
    Mat3 s;
    s << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
    return s;
}

// What a joint sees of one side: world anchor offset r from the CoM, inverse mass and inverse
// world inertia with locked DOFs masked (zero for the ground, fixed and prescribed bodies).
struct Side {
    BodyState* body = nullptr;
    V3 r = V3::Zero(), point = V3::Zero();
    Mat3 inv_m = Mat3::Zero(), inv_i = Mat3::Zero();

    V3 velocity_at() const {
        if (!body) return V3::Zero();
        return ev(body->vel) + ev(body->omega()).cross(r);
    }
    V3 omega() const { return body ? ev(body->omega()) : V3::Zero(); }
    void apply(const V3& p, const V3& angular) {
        if (!body || body->inv_mass == 0) return;
        body->vel += vec(inv_m * p);
        body->ang_mom += vec(r.cross(p) + angular);
        apply_locks(*body);
    }
};

Side side(std::vector<BodyState>& s, int index, Vec3 anchor) {
    Side out;
    if (index < 0) {
        out.point = ev(anchor);
        return out;
    }
    BodyState& b = s[index];
    out.body = &b;
    out.r = ev(rotate(b.q, anchor));
    out.point = ev(b.pos) + out.r;
    if (b.inv_mass == 0) return out;
    Mat3 mask_t = Mat3::Identity(), mask_r = Mat3::Identity();
    for (int k = 0; k < 3; ++k) {
        if (b.lock_translation[k]) mask_t(k, k) = 0;
        if (b.lock_rotation[k]) mask_r(k, k) = 0;
    }
    out.inv_m = b.inv_mass * mask_t;
    const Eigen::Quaterniond q(b.q.w, b.q.x, b.q.y, b.q.z);
    const Mat3 R = q.toRotationMatrix();
    out.inv_i = mask_r * R * ev(b.inv_inertia).asDiagonal() * R.transpose() * mask_r;
    return out;
}

// Solves K x = rhs for a possibly singular K (locked directions): least-squares inverse.
template <class M, class V> V solve(const M& k, const V& rhs) {
    return k.completeOrthogonalDecomposition().solve(rhs);
}

Vec3 world_axis(const std::vector<BodyState>& s, int index, Vec3 axis) {
    return index < 0 ? axis : rotate(s[index].q, axis);
}
Quat orientation(const std::vector<BodyState>& s, int index) {
    return index < 0 ? Quat{} : s[index].q;
}

} // namespace

void apply_locks(BodyState& b) {
    for (int k = 0; k < 3; ++k)
        if (b.lock_translation[k]) b.vel[k] = 0;
    if (!(b.lock_rotation[0] || b.lock_rotation[1] || b.lock_rotation[2])) return;
    Vec3 w = angular_velocity(b.q, b.ang_mom, b.inv_inertia);
    for (int k = 0; k < 3; ++k)
        if (b.lock_rotation[k]) w[k] = 0;
    b.ang_mom = angular_momentum(b.q, w, b.inv_inertia);
}

void JointSet::add_spring_loads(const std::vector<BodyState>& s,
                                std::vector<BodyLoads>& loads) const {
    auto& bodies = const_cast<std::vector<BodyState>&>(s);
    for (const Joint& j : joints_) {
        if (j.type != JointType::spring) continue;
        const Side a = side(bodies, j.a, j.anchor_a), b = side(bodies, j.b, j.anchor_b);
        const V3 d = b.point - a.point;
        const Real len = d.norm();
        if (len == 0) continue;
        const V3 u = d / len;
        const Real rate = (b.velocity_at() - a.velocity_at()).dot(u);
        const V3 f = (j.stiffness * (len - j.rest_length) + j.damping * rate) * u;
        if (j.a >= 0) {
            loads[j.a].joint_force += vec(f);
            loads[j.a].joint_torque += vec(a.r.cross(f));
        }
        if (j.b >= 0) {
            loads[j.b].joint_force -= vec(f);
            loads[j.b].joint_torque -= vec(b.r.cross(f));
        }
    }
}

void JointSet::project(std::vector<BodyState>& s, Real dt, int iterations, Real beta) {
    for (Joint& j : joints_) j.impulse = {};
    for (int it = 0; it < iterations; ++it) {
        for (Joint& j : joints_) {
            if (j.type == JointType::spring) continue;
            Side a = side(s, j.a, j.anchor_a), b = side(s, j.b, j.anchor_b);
            // Point constraint: anchor velocities equal, position error fed back.
            const Mat3 k = a.inv_m + b.inv_m - skew(a.r) * a.inv_i * skew(a.r) -
                           skew(b.r) * b.inv_i * skew(b.r);
            const V3 cdot = a.velocity_at() - b.velocity_at();
            const V3 err = a.point - b.point;
            const V3 p = solve(k, V3(-cdot - beta / dt * err));
            a.apply(p, V3::Zero());
            b.apply(-p, V3::Zero());
            j.impulse += vec(p / dt);
            if (j.type == JointType::ball) continue;
            // Angular constraint: relative rotation only about the hinge axis (hinge) or none
            // (fixed); the orientation error is a rotation vector.
            a = side(s, j.a, j.anchor_a), b = side(s, j.b, j.anchor_b);
            const Mat3 ki = a.inv_i + b.inv_i;
            const V3 wrel = a.omega() - b.omega();
            if (j.type == JointType::hinge) {
                const V3 ax = ev(world_axis(s, j.a, j.axis_a)).normalized();
                const V3 bx = ev(world_axis(s, j.b, j.axis_b)).normalized();
                V3 t1 = ax.unitOrthogonal(), t2 = ax.cross(t1);
                Eigen::Matrix<double, 3, 2> t;
                t << t1, t2;
                const Eigen::Matrix2d kk = t.transpose() * ki * t;
                const V3 e = ax.cross(bx); // rotate a towards b
                const Eigen::Vector2d rhs = t.transpose() * (-wrel + beta / dt * e);
                const V3 l = t * solve(kk, rhs);
                a.apply(V3::Zero(), l);
                b.apply(V3::Zero(), -l);
            } else {
                const Quat target = orientation(s, j.a) * j.rel0; // where b should be
                Quat qe = target * conjugate(orientation(s, j.b));
                if (qe.w < 0) qe = {-qe.w, -qe.x, -qe.y, -qe.z};
                const V3 e = 2 * V3(qe.x, qe.y, qe.z); // rotation taking b to its target
                const V3 l = solve(ki, V3(-wrel - beta / dt * e));
                a.apply(V3::Zero(), l);
                b.apply(V3::Zero(), -l);
            }
        }
    }
}

Real JointSet::stable_dt(const std::vector<BodyState>& s) const {
    Real dt = std::numeric_limits<Real>::max();
    for (const Joint& j : joints_) {
        if (j.type != JointType::spring || j.stiffness <= 0) continue;
        const Real inv = (j.a >= 0 ? s[j.a].inv_mass : 0) + (j.b >= 0 ? s[j.b].inv_mass : 0);
        if (inv <= 0) continue;
        const Real period = 2 * 3.14159265358979 / std::sqrt(j.stiffness * inv);
        dt = std::min(dt, Real(0.1) * period);
    }
    return dt;
}

} // namespace debrisflow::rigid
