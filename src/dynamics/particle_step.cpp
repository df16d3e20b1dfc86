// ParticleSystem::step: the refusal of degenerate rows, automatic sub-steps, one integrator
// step with its projection, and the evaluation of accelerations without a step.
#include "particle_state.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace grape {

namespace {

using detail::ConstraintRecord;
using detail::number_text;

bool all_finite(std::span<const Vec2> points) noexcept {
    for (const Vec2& p : points)
        if (!is_finite(p)) return false;
    return true;
}

}  // namespace


// The rows must be evaluated at the current state (both steps do so first).
void ParticleSystem::refuse_degenerate_rows() {
    if (state_->constraints.empty()) return;
    const auto& s = state_->solver;
    for (std::size_t r = 0; r < s.rows; ++r) {
        // C = 0 with no gradient (a user constraint at rest) asks for no force: let it be.
        if (s.gradient_norm2[r] > 0.0 || s.c[r] == 0.0) continue;
        const auto index = s.row_constraint[r];
        const ConstraintRecord& c = state_->constraints[index];
        static constexpr const char* kinds[] = {"distance", "anchor", "fixed point", "curve", "user"};
        throw Error("step: constraint " + std::to_string(index) + " (" + kinds[static_cast<int>(c.kind)] +
                    ") has a zero gradient at the current positions (C = " + number_text(s.c[r]) +
                    "): its force would have no direction; move the particles off the degenerate point");
    }
}

StepStats ParticleSystem::step(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) throw Error("step: dt must be positive and finite (got " + number_text(dt) + ")");
    if (!state_->def.substeps.automatic) return single_step(dt);
    // Equal sub-steps over what is left of dt, re-chosen after each from the latest forces.
    auto& s = state_->solver;
    StepStats report;
    double done = 0.0;
    int taken = 0;
    const SubstepDef& rule = state_->def.substeps;
    while (done < dt) {
        const double left = dt - done;
        s.look_at(state_->view());  // the system may have moved since the last step
        const double omega = s.stiffest_mode();
        const double wanted = std::ceil(omega * left / rule.omega_h);
        const int count = std::clamp(static_cast<int>(std::min(wanted, 1e9)), 1, std::max(1, rule.max - taken));
        const bool last = count == 1;
        const double h = last ? left : left / count;
        const StepStats r = single_step(h);
        ++taken;
        report.evaluations += r.evaluations;
        report.rejected += r.rejected;
        report.forced += r.forced;
        report.projection_iterations += r.projection_iterations;
        report.cg_iterations += r.cg_iterations;
        report.status = worse(report.status, r.status);
        if (r.status == SolveStatus::non_finite) break;
        done = last ? dt : done + h;
    }
    report.substeps = taken;
    return report;
}

StepStats ParticleSystem::single_step(double dt) {
    auto& s = state_->solver;
    s.prepare(state_->view(), dt);
    StepStats report;
    if (state_->def.integrator == Integrator::rattle) {
        if (s.rows > 0) s.evaluate_rows(state_->positions, state_->velocities);  // the step's start, as rattle_step reads it
        refuse_degenerate_rows();
        const bool ok = s.rattle_step(state_->time, state_->positions, state_->velocities, dt, report.projection_iterations);
        report.evaluations = s.evaluations;
        report.substeps = 1;
        report.cg_iterations = s.cg_iterations;
        std::fill(state_->exerted.begin(), state_->exerted.end(), Vec2{});
        if (!ok) {
            report.status = SolveStatus::non_finite;
            return report;
        }
        state_->time += dt;
        report.status = s.worst;
        return report;
    }
    // The rows at the step's start (prepare() looked at the system), for the refusal and for
    // the integrator's first stage, which reuses them.
    if (s.rows > 0) s.evaluate_rows_for_step(state_->positions, state_->velocities);
    refuse_degenerate_rows();
    const std::span<double> q(reinterpret_cast<double*>(state_->positions.data()), 2 * state_->positions.size());
    const std::span<double> v(reinterpret_cast<double*>(state_->velocities.data()), 2 * state_->velocities.size());
    const StepStats stats = state_->stepper.step(s, state_->time, q, v, dt);
    report.evaluations = s.evaluations;
    report.substeps = stats.substeps;
    report.rejected = stats.rejected;
    report.forced = stats.forced;
    if (stats.status == SolveStatus::non_finite) {
        // The stepper left q and v as they were: say so, and do not advance the clock.
        report.status = SolveStatus::non_finite;
        report.cg_iterations = s.cg_iterations;
        std::fill(state_->exerted.begin(), state_->exerted.end(), Vec2{});
        return report;
    }
    state_->time += dt;
    if (stats.status == SolveStatus::substep_limit) s.note(SolveStatus::substep_limit);
    if (state_->def.drift.method == DriftControl::projection) {
        state_->saved_positions.assign(state_->positions.begin(), state_->positions.end());
        state_->saved_velocities.assign(state_->velocities.begin(), state_->velocities.end());
        report.projection_iterations = s.project(state_->positions, state_->velocities);
        if (!all_finite(state_->positions) || !all_finite(state_->velocities)) {
            state_->positions.swap(state_->saved_positions);
            state_->velocities.swap(state_->saved_velocities);
            s.note(SolveStatus::non_finite);
        }
    }
    report.status = s.worst;
    report.cg_iterations = s.cg_iterations;
    std::fill(state_->exerted.begin(), state_->exerted.end(), Vec2{});
    return report;
}

double ParticleSystem::stiffest_mode() const noexcept {
    auto& s = state_->solver;
    if (s.dirty) return 0.0;
    s.look_at(state_->view());
    return s.stiffest_mode();
}

SolveStatus ParticleSystem::evaluate(std::span<Vec2> accelerations) {
    auto& s = state_->solver;
    s.prepare(state_->view(), 0.0);
    if (accelerations.size() < state_->positions.size())
        throw Error("evaluate: accelerations must hold one entry per particle (got " +
                    std::to_string(accelerations.size()) + " for " + std::to_string(state_->positions.size()) + ")");
    const std::span<const double> q(reinterpret_cast<const double*>(state_->positions.data()), 2 * state_->positions.size());
    const std::span<const double> v(reinterpret_cast<const double*>(state_->velocities.data()), 2 * state_->velocities.size());
    s.acceleration(state_->time, q, v, {reinterpret_cast<double*>(accelerations.data()), 2 * state_->positions.size()});
    return s.worst;
}


}  // namespace grape
