#!/bin/sh
# The work `grape render` takes on for a scene's simulations is bounded: refused before it
# runs when the count says it is too much (exit 2, the simulation and the bound named), and
# stopped with a clear message when a step cannot be trusted. Exits 0 (as expected) or 1.
#   tests/tool_render_work.sh CASE GRAPE WORKDIR
set -u
. "$(dirname "$0")/tool_case.sh"
# run CMD...: status in $work/status, stderr in $work/err
run() {
    "$@" >"$work/out" 2>"$work/err"
    echo $? >"$work/status"
    echo "status $(cat "$work/status"); stderr:"
    cat "$work/err"
}
expect_error() {  # expect_error TEXT: status 2, TEXT (fixed string) on stderr, no picture
    [ "$(cat "$work/status")" = 2 ] || fail "exit status $(cat "$work/status"), expected 2"
    grep -qF -- "$1" "$work/err" || fail "stderr does not say '$1'"
    [ ! -e "$work/out.png" ] || fail "a picture was written"
}
# simulation NAME INTEGRATOR DT DURATION: one pendulum on an anchor.
simulation() {
    printf '{"name": "%s", "integrator": "%s", "dt": %s, "duration": %s, "particles": [{"position": [100, 0]}], "forces": [{"kind": "gravity", "acceleration": [0, 500]}], "constraints": [{"kind": "anchor", "a": 0, "point": [0, 0], "length": 100}]}' "$1" "$2" "$3" "$4"
}

case $case_name in
work_budget)
    # 1e6 steps of dt = 1e-4 to t = 100 s, in the world box's run and the picture's (2e6),
    # counted at 601 evaluations a step for rk45 (6 for each of up to 100 sub-steps, and the
    # first) for 1 particle and 1 constraint: 2.4e9, over the budget of 5e7.
    printf '{"view": {"width": 64, "height": 48}, "simulations": [%s]}\n' "$(simulation long rk45 1e-4 100)" >"$work/long.json"
    run "$grape" render "$work/long.json" -o "$work/out.png" --time 100
    expect_error "render: the scene's simulations need up to 2.4e+09 force evaluations × particles and constraints, more than the budget of 5e+07; the heaviest, simulation 'long' (/simulations/0), takes 2e+06 steps of rk45 with up to 601 evaluations each for 2 particles and constraints (use a larger dt, a shorter duration, or --force to render it anyway)"
    # At t = 0 only the box's run of 20000 steps counts: 2.4e7, within the budget.
    run "$grape" render "$work/long.json" -o "$work/out.png"
    [ "$(cat "$work/status")" = 0 ] || fail "refused at t = 0"
    ;;
many_simulations)
    # 8000 simulations of one rk45 step of dt = 1e10 (before: over 60 s). Within the work
    # budget (8000 × 2 steps × 601 × 2 = 1.9e7), so it runs, and the first step reaches the
    # cap of 100 sub-steps: stopped at once, naming the simulation.
    {
        printf '{"view": {"width": 64, "height": 48}, "simulations": ['
        i=0
        while [ $i -lt 8000 ]; do
            [ $i = 0 ] || printf ', '
            simulation s$i rk45 1e10 1e10
            i=$((i + 1))
        done
        printf ']}\n'
    } >"$work/many.json"
    start=$(date +%s)
    run "$grape" render "$work/many.json" -o "$work/out.png"
    elapsed=$(( $(date +%s) - start ))
    expect_error "simulation 's0' (/simulations/0): rk45 needs more than 100 sub-steps for the step at t = 0 s (dt = 1e+10 s is too long for its tolerance, or the system is stiff; try a smaller dt)"
    [ $elapsed -le 20 ] || fail "took $elapsed s"
    ;;
trails)
    # The world box records every particle after every step: to t = 10⁴ s at dt = 1e-3 that is
    # 1e7 steps × 10 particles × 16 bytes = 1.5 GiB, past the memory budget of 1 GiB (the
    # work budget raised out of the way, to check the memory one).
    parts='{"position": [0, 0]}'
    k=1
    while [ $k -lt 10 ]; do parts="$parts, {\"position\": [$k, 0]}"; k=$((k + 1)); done
    printf '{"view": {"width": 64, "height": 48}, "simulations": [{"name": "dust", "integrator": "euler", "dt": 1e-3, "duration": 1e4, "particles": [%s]}]}\n' "$parts" >"$work/dust.json"
    run "$grape" render "$work/dust.json" -o "$work/out.png" --time 1e4 --simulation-budget 1e12
    expect_error "render: recording the scene's simulations for the picture's bounds needs about 1.5 GiB, more than the budget of 1.0 GiB; the heaviest is simulation 'dust' (/simulations/0) (use a larger dt, a shorter duration, or --force to render it anyway)"
    ;;
non_finite)
    # A step that leaves the finite range stops the render (before: the player stepped it for ever).
    printf '{"view": {"width": 64, "height": 48}, "simulations": [{"name": "fast", "integrator": "euler", "dt": 1, "duration": 100, "particles": [{"position": [0, 0], "velocity": [1e300, 0]}], "forces": [{"kind": "gravity", "acceleration": [1e308, 0]}]}]}\n' >"$work/fast.json"
    run "$grape" render "$work/fast.json" -o "$work/out.png"
    expect_error "simulation 'fast' (/simulations/0): the step at t = "
    grep -qF "s leaves the finite range" "$work/err" || fail "not said"
    ;;
*)
    fail "unknown case $case_name"
    ;;
esac
echo "ok"
