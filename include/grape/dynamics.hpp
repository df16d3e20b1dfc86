// grape — dynamics: particles, forces, integrators, Witkin constraints, drift control and
// beads on any path.
//
// Two ways to keep a particle on a curve, as in the seed's parabola x² + 100y = 0:
//  * implicit (Witkin): a ParticleSystem with a constraint C(q) = 0. Each evaluation solves
//    J W Jᵀ λ = −J̇q̇ − J W Q − ks·C − kd·Ċ and applies the constraint force Jᵀλ, which does
//    no work along any legal velocity. Any number of particles and constraints, solved
//    together (Cholesky for small or banded systems, Eigen's sparse solvers for large ones).
//  * generalized coordinates (Lagrange): a Bead with one coordinate u on a parametric curve
//    x(u) (any grape::Path), q̈ = (x′·F/m − (x′·x″) q̇²)/|x′|². On the curve by construction.
//
// The seed's closed-form constraint force for the parabola,
//   Fc.y = (−50 m vx² − 100 x Fext.x − 2500 Fext.y)/(x² + 2500),  Fc.x = Fc.y·x/50,
// has the wrong coefficient on Fext.x: Jᵀλ (and the seed's own no-work argument) gives
// −50·x·Fext.x. With gravity alone the two agree; with any sideways force the seed's force
// leaves C̈ = −2·x·Fext.x/m and pushes the bead off the curve. The general solver below gives
// the corrected force (tests/test_dynamics.cpp checks both).
//
// Units: any consistent set (the seed uses pixels, seconds, mass 1, y down, g = (0, +g)).
//
//   grape::ParticleSystem system({.integrator = grape::Integrator::rk4});
//   auto bob = system.create_particle({.position = {100, 0}});
//   system.add_gravity({0, 500});
//   system.create_anchor(bob, {0, 0}, 100);       // a pendulum of length 100
//   for (int i = 0; i < 60; ++i) system.step(1.0 / 60);
//
// Threads: a ParticleSystem, a Bead and a Stepper each belong to one thread (step, add,
// queries and the force functions they call). Separate systems and beads share nothing and
// may step on separate threads at once, also when they read the same Path (shared
// read-only), or the same ImplicitFunction if its function is safe to call concurrently.
// The parse_* and to_string functions may be called from any thread.
//
// The parts, one idea per header (this one includes them all):
//   <grape/dynamics_implicit.hpp>   ImplicitFunction, ImplicitSample (and <grape/jet.hpp>: Jet2)
//   <grape/dynamics_ode.hpp>        Integrator, Stepper, SecondOrderSystem, StepStats
//   <grape/dynamics_particles.hpp>  ParticleSystem, constraints, drift, GrabDef, SubstepDef
//   <grape/dynamics_bead.hpp>       Bead, ParametricSample, ParametricFunction
#pragma once

#include <grape/dynamics_bead.hpp>
#include <grape/dynamics_implicit.hpp>
#include <grape/dynamics_jet.hpp>
#include <grape/dynamics_ode.hpp>
#include <grape/dynamics_particles.hpp>
