#!/bin/sh
# `grape sample` as a user runs it: the JSON it prints for a small timeline scene whose
# positions follow by hand, and its errors (exit status 2, the reason on stderr, nothing on
# stdout). Each case prints what it saw and exits 0 (as expected) or 1 (not).
#   tests/tool_sample.sh CASE GRAPE WORKDIR SCENES_DIR
set -u
. "$(dirname "$0")/tool_case.sh"
run() {  # run CMD...: status in $status, stdout in $work/out, stderr in $work/err
    "$@" >"$work/out" 2>"$work/err"
    status=$?
    echo "status $status; stdout:"
    cat "$work/out"
    echo "stderr:"
    cat "$work/err"
}
expect_error() {  # expect_error TEXT: status 2, TEXT (fixed string) on stderr, stdout empty
    [ "$status" = 2 ] || fail "exit status $status, expected 2"
    grep -qF -- "$1" "$work/err" || fail "stderr does not say '$1'"
    [ ! -s "$work/out" ] || fail "printed something on stdout"
}

# Timeline t: delay 1, a (1 s along x to 100) at 0, b (1 s along y to 10) at a's start + 1,
# so one play lasts 2 s; it plays twice with 0.5 s between, the second time backwards (scene
# times 3.5 to 5.5). c runs free: 4 s from (0, 0) to (1, 1). Every time below is a sum of
# powers of two, so the positions are exact. By hand, at scene time
#   0     t waits:                      a, b at their starts; c at 0
#   1.25  t at 0.25:                    a at u = 0.25; b not started
#   2.5   t at 1.5:                     a ended; b 0.5 s in
#   3.25  t's repeat delay, held at 2:  a, b at their ends
#   3.75  t backwards 0.25 s in, at 1.75: a at its end; b 0.75 s in
#   4.75  t backwards 1.25 s in, at 0.75: a at u = 0.75; b back at its start
#   10    t ended at its start:         a, b at their starts; c at its end
cat >"$work/scene.json" <<'JSON'
{"animations": [
  {"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [100, 0]}, "duration": 1},
  {"name": "b", "path": {"kind": "linear", "start": [0, 0], "end": [0, 10]}, "duration": 1},
  {"name": "c", "path": {"kind": "linear", "start": [0, 0], "end": [1, 1]}, "duration": 4},
  {"path": {"kind": "linear", "start": [0, 0], "end": [1, 1]}, "duration": 3}],
 "timelines": [{"name": "t", "delay": 1, "repeat": 1, "repeat_delay": 0.5, "yoyo": true,
                "children": [{"animation": "a"}, {"animation": "b", "at": "<+1"}]}]}
JSON

# Properties by hand: x by 10 over 1 s, then by −4 over 0.5 s after it in a timeline (from
# where the first left it); a colour from black to white over 1 s; a vec2 from [0, 0] to
# [2, 4] over 2 s after a delay of 1 s; an angle from 350° to 10° the short way (to 370°).
# At 0: the initial values (v waiting); at 1.25: x 10 − 2, white, v 1/8 of the way, 370; at
# 2: x 6, v half way.
cat >"$work/props.json" <<'JSON'
{"properties": [{"name": "x", "value": 0}, {"name": "c", "type": "color", "value": "#000000"},
            {"name": "v", "type": "vec2", "value": [0, 0]},
            {"name": "a", "type": "angle", "value": 350, "unit": "degrees"}],
 "tweens": [{"name": "up", "property": "x", "by": 10, "duration": 1},
        {"name": "back", "property": "x", "by": -4, "duration": 0.5},
        {"property": "c", "to": "#ffffff", "duration": 1},
        {"property": "v", "from": [0, 0], "to": [2, 4], "duration": 2, "delay": 1},
        {"property": "a", "to": 10, "duration": 1}],
 "timelines": [{"name": "t", "children": [{"tween": "up"}, {"tween": "back"}]}]}
JSON

case $case_name in
values)
    run "$grape" sample "$work/scene.json" --at 0,1.25,2.5,3.25,3.75,4.75,10
    [ "$status" = 0 ] || fail "exit status $status"
    cat >"$work/expected" <<'OUT'
[{"time": 0, "animations": {"a": [0, 0], "b": [0, 0], "c": [0, 0]}},
 {"time": 1.25, "animations": {"a": [25, 0], "b": [0, 0], "c": [0.3125, 0.3125]}},
 {"time": 2.5, "animations": {"a": [100, 0], "b": [0, 5], "c": [0.625, 0.625]}},
 {"time": 3.25, "animations": {"a": [100, 0], "b": [0, 10], "c": [0.8125, 0.8125]}},
 {"time": 3.75, "animations": {"a": [100, 0], "b": [0, 7.5], "c": [0.9375, 0.9375]}},
 {"time": 4.75, "animations": {"a": [75, 0], "b": [0, 0], "c": [1, 1]}},
 {"time": 10, "animations": {"a": [0, 0], "b": [0, 0], "c": [1, 1]}}]
OUT
    diff "$work/expected" "$work/out" || fail "not the positions derived by hand"
    ;;
digits)
    # A third of a 3 s linear animation: u = 1/3 printed with 17 significant digits.
    sed 's/"name": "c", \(.*\)"duration": 4/"name": "c", \1"duration": 3/' "$work/scene.json" >"$work/third.json"
    run "$grape" sample "$work/third.json" --at 1
    [ "$status" = 0 ] || fail "exit status $status"
    grep -qxF '[{"time": 1, "animations": {"a": [0, 0], "b": [0, 0], "c": [0.33333333333333331, 0.33333333333333331]}}]' "$work/out" ||
        fail "not 1/3 with 17 significant digits"
    ;;
round_trip)
    # 17 significant digits: every number printed is the %.17g text of the double it reads
    # back as (a shorter or longer form, such as %g's 6 digits, would differ).
    run "$grape" sample "$scenes/timeline_cutscene.json" --at 0.1,1.7,3.3,4.4,6.05,9.99
    [ "$status" = 0 ] || fail "exit status $status"
    numbers=$(tr -c '0-9.eE+-' '\n' <"$work/out" | grep '[0-9]' | grep -v '^[+-]*$')
    [ -n "$numbers" ] || fail "no numbers"
    for n in $numbers; do
        again=$(awk -v x="$n" 'BEGIN { printf "%.17g", x + 0 }')
        [ "$n" = "$again" ] || fail "$n is not 17 significant digits of the double it reads as ($again)"
    done
    for name in slide drop spin pulse wave; do
        [ "$(grep -o "\"$name\": \[" "$work/out" | wc -l)" = 6 ] || fail "$name is not at every time"
    done
    ;;
properties)
    run "$grape" sample "$work/props.json" --at 0,1.25,2
    [ "$status" = 0 ] || fail "exit status $status"
    cat >"$work/expected" <<'OUT'
[{"time": 0, "animations": {}, "properties": {"x": 0, "c": [0, 0, 0, 1], "v": [0, 0], "a": 350}},
 {"time": 1.25, "animations": {}, "properties": {"x": 8, "c": [1, 1, 1, 1], "v": [0.25, 0.5], "a": 370}},
 {"time": 2, "animations": {}, "properties": {"x": 6, "c": [1, 1, 1, 1], "v": [1, 2], "a": 370}}]
OUT
    diff "$work/expected" "$work/out" || fail "not the values derived by hand"
    ;;
bad_property)
    sed 's/"property": "c"/"property": "colour"/' "$work/props.json" >"$work/bad.json"
    run "$grape" sample "$work/bad.json" --at 0
    expect_error "bad.json: scene: /tweens/2/property: no property named \"colour\" in /properties"
    ;;
bad_time)
    run "$grape" sample "$work/scene.json" --at 0,soon
    expect_error "sample: --at must be a finite number (got 'soon')"
    ;;
unknown_label)
    sed 's/"<+1"/"later+1"/' "$work/scene.json" >"$work/bad.json"
    run "$grape" sample "$work/bad.json" --at 0
    expect_error "bad.json: scene: /timelines/0/children/1/at: "
    grep -qF "later" "$work/err" || fail "stderr does not name the label"
    ;;
duplicate_names)
    # The unnamed animation named like c: a JSON object cannot hold both.
    sed 's/^  {"path"/  {"name": "c", "path"/' "$work/scene.json" >"$work/dup.json"
    run "$grape" sample "$work/dup.json" --at 0
    expect_error "/animations/2 and /animations/3 are both named \"c\""
    ;;
missing_file)
    run "$grape" sample "$work/none.json" --at 0
    expect_error "cannot read $work/none.json: no such file"
    ;;
*)
    fail "unknown case $case_name"
    ;;
esac
echo "ok: $case_name"
