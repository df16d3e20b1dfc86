#!/bin/sh
# `grape render --view`: the scenes' 3-D paths and animations projected. Each view kind draws
# the 3-D example scenes (PNG and SVG, checked by check_render.py), frames move, a follower
# lands where the projection puts it (check_render3.py works the pixel out on its own), and a
# bad spec exits 2 naming --view and the reason. Exits 0 (as expected), 1, or 77 (no python3).
#   tests/tool_render3.sh CASE GRAPE WORKDIR SCENES_DIR
set -u
. "$(dirname "$0")/tool_case.sh"
tests=$(dirname "$0")
command -v python3 >/dev/null 2>&1 || { echo "no python3"; exit 77; }
# render ARGS...: must exit 0
render() {
    "$grape" render "$@" >"$work/out" 2>"$work/err" || { cat "$work/err"; fail "grape render $* exited $?"; }
}
# refused SPEC MESSAGE: exit 2, MESSAGE (fixed string) as stderr's line, no picture
refused() {
    "$grape" render "$scenes/camera_rail3d.json" -o "$work/bad.png" --view "$1" >"$work/out" 2>"$work/err"
    status=$?
    [ $status = 2 ] || fail "--view '$1': exit status $status, expected 2"
    [ "$(cat "$work/err")" = "$2" ] || fail "--view '$1': stderr is '$(cat "$work/err")', expected '$2'"
    [ ! -e "$work/bad.png" ] || fail "--view '$1': a picture was written"
}

case $case_name in
view_kinds)
    for scene in camera_rail3d coaster_banked; do
        for view in oblique oblique:30,0.5 perspective perspective:120,20,60 perspective:-30,-40; do
            name=$(printf '%s' "$scene-$view" | tr ':,.' '___')
            for ext in png svg; do
                render "$scenes/$scene.json" -o "$work/$name.$ext" --time 2.5 --view "$view"
                python3 "$tests/check_render.py" --width 640 --height 480 "$work/$name.$ext" || fail "$name.$ext"
            done
        done
        # Without --view: the oblique default, the same picture as --view oblique.
        render "$scenes/$scene.json" -o "$work/$scene-default.png" --time 2.5
        cmp -s "$work/$scene-default.png" "$work/$scene-oblique.png" || fail "$scene: the default is not --view oblique"
    done
    ;;
frames)
    # The car goes round at 20 units/s: frames 0.5 s apart differ; the animated SVG moves too.
    render "$scenes/coaster_banked.json" -o "$work/car.png" --frames 3 --fps 2 --view perspective
    cmp -s "$work/car-0001.png" "$work/car-0003.png" && fail "frames 1 and 3 are the same picture"
    render "$scenes/coaster_banked.json" -o "$work/car.svg" --frames 4 --fps 2 --view oblique:45,0.5
    python3 "$tests/check_render.py" --width 640 --height 480 "$work/car.svg" || fail "car.svg"
    grep -q "animateMotion\|<animate" "$work/car.svg" || fail "the animated SVG does not animate"
    ;;
follower_position)
    # One follower on the line from (0, 0, 0) to (20, 10, 8) over 4 s, linear: at t = 1 s it is
    # a quarter of the way, at (5, 2.5, 2); the content box is the segment's.
    cat >"$work/line.json" <<'JSON'
{"grape_scene": 1, "view": {"width": 400, "height": 300},
 "animations3": [{"path": {"kind": "line", "points": [[0, 0, 0], [20, 10, 8]]}, "duration": 4,
                  "align": "frame", "frame": {"mode": "up", "up": [0, 0, 1]}}]}
JSON
    for view in oblique oblique:30,0.5 perspective perspective:150,-20,70; do
        name=$(printf '%s' "$view" | tr ':,.' '___')
        render "$work/line.json" -o "$work/$name.png" --time 1 --view "$view"
        python3 "$tests/check_render3.py" "$work/$name.png" "$view" 400 300 0,0,0,20,10,8 5,2.5,2 || fail "$view: misplaced"
    done
    ;;
bad_view)
    refused cavalier "grape: render: --view 'cavalier': unknown view 'cavalier' (expected oblique, oblique:ANGLE_DEG,RECEDE, perspective or perspective:AZIMUTH_DEG,ELEVATION_DEG[,FOV_DEG])"
    refused oblique:30 "grape: render: --view 'oblique:30': expected oblique:ANGLE_DEG,RECEDE (two numbers)"
    refused oblique:30,1.5 "grape: render: --view 'oblique:30,1.5': RECEDE must lie in (0, 1] (got 1.5)"
    refused oblique:30,x "grape: render: --view 'oblique:30,x': RECEDE must be a finite number (got 'x')"
    refused oblique:nan,0.5 "grape: render: --view 'oblique:nan,0.5': ANGLE_DEG must be a finite number (got 'nan')"
    refused perspective:10 "grape: render: --view 'perspective:10': expected perspective:AZIMUTH_DEG,ELEVATION_DEG[,FOV_DEG] (two or three numbers)"
    refused perspective:10,90 "grape: render: --view 'perspective:10,90': ELEVATION_DEG must lie in [-89, 89] (got 90)"
    refused perspective:10,20,1 "grape: render: --view 'perspective:10,20,1': FOV_DEG must lie in [5, 120] (got 1)"
    refused perspective:1,2,30,4 "grape: render: --view 'perspective:1,2,30,4': takes at most 3 numbers"
    refused perspective:1,,30 "grape: render: --view 'perspective:1,,30': ELEVATION_DEG must be a finite number (got '')"
    refused perspective:1e999,20 "grape: render: --view 'perspective:1e999,20': AZIMUTH_DEG must be a finite number (got '1e999')"
    # A scene without 3-D content has nothing to project.
    "$grape" render "$scenes/seed_bezier.json" -o "$work/flat.png" --view oblique >"$work/out" 2>"$work/err"
    [ $? = 2 ] || fail "a 2-D scene with --view: not exit 2"
    grep -qF "render: --view: " "$work/err" && grep -qF "has no 3-D paths or animations (paths3, animations3) to project" "$work/err" ||
        fail "a 2-D scene with --view: stderr is '$(cat "$work/err")'"
    ;;
long_paths)
    # A helix of 10⁵ turns of radius 10 is 6.3·10⁶ long: on a 640×480 picture of its 20 × 20 ×
    # 100 box it is far over the budget of 10⁶ output units, refused before it is flattened.
    printf '{"grape_scene": 1, "paths3": [{"name": "coil", "path": {"kind": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "start": [1, 0, 0], "radius": 10, "rise_per_turn": 0.001, "turns": 100000}}]}\n' >"$work/coil.json"
    "$grape" render "$work/coil.json" -o "$work/coil.png" --view perspective >"$work/out" 2>"$work/err"
    [ $? = 2 ] || fail "the coil was not refused"
    grep -qF "units long on the picture (3-D path 'coil': " "$work/err" || fail "stderr is '$(cat "$work/err")'"
    [ ! -e "$work/coil.png" ] || fail "a picture was written"
    ;;
*)
    fail "unknown case $case_name"
    ;;
esac
echo "ok"
