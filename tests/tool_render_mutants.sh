#!/bin/sh
# `grape render` over mutated scenes: the scene mutator (test_scene_mutator, seeded) writes
# the mutants that loaded, and each is rendered until COUNT renders or SECONDS of wall time,
# whichever comes first. Every render must exit 0 (drawn) or 2 (refused with a message on
# stderr) within PER_RENDER seconds: never crash, trap (sanitizers), hang or fail otherwise.
# Exits 0 (as expected) or 1, printing the mutant that failed.
#   tests/tool_render_mutants.sh MUTATOR GRAPE WORKDIR COUNT SECONDS PER_RENDER
# GRAPE_MUTATOR_SEED (environment) picks other mutants (default 18).
set -u
mutator=$1
grape=$2
work=$3
count=$4
seconds=$5
per_render=$6
rm -rf "$work"
mkdir -p "$work/scenes"

fail() {
    echo "FAIL: $*"
    exit 1
}

GRAPE_MUTANT_DIR="$work/scenes" GRAPE_MUTATOR_SEED=${GRAPE_MUTATOR_SEED:-18} GRAPE_MUTATOR_ROUNDS=600 \
    "$mutator" --gtest_filter=SceneMutator.LoadsOrRefusesEveryMutant >"$work/mutator.log" 2>&1 ||
    { cat "$work/mutator.log"; fail "the scene mutator failed"; }
total=$(ls "$work/scenes" | wc -l)
[ "$total" -gt 0 ] || fail "the mutator wrote no scenes"

start=$(date +%s)
drawn=0
refused=0
i=0
# A small work budget (1e6 evaluations, ~0.2 s here) keeps each render short under the
# sanitizers too; what goes past it is refused with exit 2, itself a case to check.
while [ $i -lt "$total" ] && [ $((drawn + refused)) -lt "$count" ] && [ $(($(date +%s) - start)) -lt "$seconds" ]; do
    scene="$work/scenes/mutant-$i.json"
    i=$((i + 1))
    [ -e "$scene" ] || continue
    timeout -s KILL "$per_render" "$grape" render "$scene" -o "$work/out.png" --simulation-budget 1e6 \
        >"$work/out.txt" 2>"$work/err.txt"
    status=$?
    case $status in
    0) drawn=$((drawn + 1)) ;;
    2)
        refused=$((refused + 1))
        grep -q "^grape" "$work/err.txt" || { head -c 2000 "$scene"; echo; fail "exit 2 without a message"; }
        ;;
    137) head -c 2000 "$scene"; echo; fail "$scene took more than $per_render s" ;;
    *) cat "$work/err.txt"; head -c 2000 "$scene"; echo; fail "$scene: exit status $status" ;;
    esac
done
echo "$((drawn + refused)) of $total mutants rendered in $(($(date +%s) - start)) s: $drawn drawn, $refused refused"
# Some of both, at least (renders are bounded by time, so the counts are loose under load).
[ "$drawn" -ge 1 ] || fail "no mutant was drawn"
echo "ok"
