// Two scenes every integrator's tests run: a user constraint against its built-in twin, and a
// fixed point held against gravity and a spring.
#pragma once

#include <grape/dynamics.hpp>

#include <span>

namespace grape::testing {

// Witkin's bead on the unit circle written as a user constraint, C = ½(|x|² − 1), beside the
// built-in anchor of radius 1 on the same particle: 240 steps of 1/240 s under gravity.
struct CircleTwins {
    Vec2 anchor, user;       // the particle's final positions
    double anchor_residual;  // the anchor system's max_residual().distance
};
inline CircleTwins circle_twins(const ParticleSystemDef& def) {
    ParticleSystem anchor(def), user(def);
    for (ParticleSystem* s : {&anchor, &user}) {
        const auto p = s->create_particle({.position = {0.6, 0.8}, .velocity = {-1, 0.75}});
        s->add_gravity({0, 9.81});
        if (s == &anchor) {
            s->create_anchor(p, {0, 0}, 1.0);
        } else {
            s->create_constraint({{p}, [](std::span<const Vec2> x, std::span<const Vec2> v, UserConstraintOutput& out) {
                                   out.value = 0.5 * (dot(x[0], x[0]) - 1.0);
                                   out.jacobian[0] = x[0];
                                   out.jdot_v = dot(v[0], v[0]);
                               }});
        }
    }
    for (int i = 0; i < 240; ++i) {
        anchor.step(1.0 / 240);
        user.step(1.0 / 240);
    }
    return {anchor.positions()[0], user.positions()[0], anchor.max_residual().distance};
}

// A particle fixed at the origin, tied by a spring (rest 0.5, stiffness 50) to one at (1, 0),
// under gravity: 240 steps of 1/240 s. The final positions of both.
struct FixedAndFree {
    Vec2 fixed, free;
};
inline FixedAndFree fixed_point_against_spring(const ParticleSystemDef& def) {
    ParticleSystem system(def);
    const auto a = system.create_particle({.position = {0, 0}});
    const auto b = system.create_particle({.position = {1, 0}});
    system.add_gravity({0, 9.81});
    system.add_spring(a, b, {.rest_length = 0.5, .stiffness = 50});
    system.create_fixed_point(a, {0, 0});
    for (int i = 0; i < 240; ++i) system.step(1.0 / 240);
    return {system.positions()[0], system.positions()[1]};
}

}  // namespace grape::testing
