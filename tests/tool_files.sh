#!/bin/sh
# `grape` writing files as a user would meet it: full disks, folders in the way, Ctrl-C during
# a run of frames. Each case prints what it saw and exits 0 (as expected), 1 (not) or 77
# (skipped, with the reason).
#   tests/tool_files.sh CASE GRAPE WORKDIR SCENES_DIR
# A full disk is either a small tmpfs mounted for the case (when mounting is permitted) or a
# file size limit of 0 (ulimit -f 0, SIGXFSZ ignored: every write fails with EFBIG, "file too
# large"). The tool's temporaries are created exclusively under names of their own, so a link
# planted at a temporary's name is never written through.
set -u
. "$(dirname "$0")/tool_case.sh"
# expect_error STATUS_FILE STDERR_FILE TEXT: status 2 and TEXT (fixed string) on stderr.
expect_error() {
    status=$(cat "$1")
    echo "status $status; stderr:"
    cat "$2"
    [ "$status" = 2 ] || fail "exit status $status, expected 2"
    grep -qF -- "$3" "$2" || fail "stderr does not say '$3'"
}
# nothing_left DIR: DIR holds no file at all (no frames, no temporary, no empty file).
nothing_left() {
    left=$(ls -A "$1")
    [ -z "$left" ] || fail "files left behind in $1: $left"
}
run() {  # run CMD...: status in $work/status, stderr in $work/err, stdout in $work/out
    "$@" >"$work/out" 2>"$work/err"
    echo $? >"$work/status"
}
run_full() {  # run_full CMD...: as run, on a disk where every write fails
    # Its stdout and stderr go through pipes to files written without the limit.
    mkfifo "$work/err.fifo"
    cat "$work/err.fifo" >"$work/err" &
    { (ulimit -f 0 && trap '' XFSZ && exec "$@") 2>"$work/err.fifo"; echo $? >"$work/status"; } | cat >"$work/out"
    wait
    rm "$work/err.fifo"
}

case $case_name in
full_disk_png_frames)
    # The second frame cannot be written (a folder in its place): exit 2 naming it, the first
    # frame removed, the folder left as it was.
    mkdir "$work/out.d" "$work/out.d/f-0002.png"
    run "$grape" render "$scenes/seed_parabola.json" -o "$work/out.d/f.png" --frames 3 --fps 10
    expect_error "$work/status" "$work/err" "cannot write $work/out.d/f-0002.png: it is a folder"
    [ "$(ls -A "$work/out.d")" = f-0002.png ] || fail "files left: $(ls -A "$work/out.d")"
    # Every frame on a full disk: nothing left.
    rmdir "$work/out.d/f-0002.png"
    run_full "$grape" render "$scenes/seed_parabola.json" -o "$work/out.d/f.png" --frames 3 --fps 10
    expect_error "$work/status" "$work/err" "cannot write $work/out.d/f-0001.png: file too large"
    nothing_left "$work/out.d"
    ;;
full_disk_pdf)
    mkdir "$work/out.d"
    run_full "$grape" render "$scenes/pendulum_chain.json" -o "$work/out.d/chain.pdf" --time 1
    expect_error "$work/status" "$work/err" "cannot write $work/out.d/chain.pdf: file too large"
    nothing_left "$work/out.d"
    ;;
full_disk_keeps_old)
    # A picture replaces its file only when complete: a failed render leaves the old one.
    mkdir "$work/out.d"
    echo old >"$work/out.d/s.png"
    run_full "$grape" render "$scenes/seed_spiral.json" -o "$work/out.d/s.png"
    expect_error "$work/status" "$work/err" "cannot write $work/out.d/s.png: file too large"
    [ "$(cat "$work/out.d/s.png")" = old ] || fail "the old picture was lost"
    [ "$(ls -A "$work/out.d")" = s.png ] || fail "files left: $(ls -A "$work/out.d")"
    ;;
full_disk_animated_svg)
    mkdir "$work/out.d"
    run_full "$grape" render "$scenes/seed_bezier.json" -o "$work/out.d/b.svg" --frames 20
    expect_error "$work/status" "$work/err" "cannot write $work/out.d/b.svg: file too large"
    nothing_left "$work/out.d"
    ;;
full_disk_csv)
    mkdir "$work/out.d"
    run_full "$grape" simulate parabola --dt 0.001 --seconds 10 --csv "$work/out.d/run.csv"
    expect_error "$work/status" "$work/err" "cannot write $work/out.d/run.csv: file too large"
    [ ! -s "$work/out" ] || fail "printed a result although the CSV was not written"
    nothing_left "$work/out.d"
    ;;
tmpfs)
    # A real full disk: a 256 KiB tmpfs. A 300 KB PDF, a CSV, and 1000 frames that would not fit
    # (refused after the first frame with the estimate).
    if ! mkdir -p "$work/disk" || ! mount -t tmpfs -o size=256k tmpfs "$work/disk" 2>"$work/mount-err"; then
        echo "mounting a tmpfs is not permitted here ($(cat "$work/mount-err")); the /dev/full cases cover full disks"
        exit 77
    fi
    trap 'umount "$work/disk"' EXIT
    echo "mounted a 256 KiB tmpfs at $work/disk: a real full disk ($(df -k "$work/disk" | awk 'NR == 2 { print $4 }') KiB free)"
    head -c 200000 /dev/zero >"$work/disk/filler"  # leaves ~56 KiB
    run "$grape" simulate parabola --dt 0.0001 --seconds 10 --csv "$work/disk/run.csv"
    expect_error "$work/status" "$work/err" "cannot write $work/disk/run.csv: no space left on device"
    [ "$(ls -A "$work/disk")" = filler ] || fail "a partial CSV is left: $(ls -A "$work/disk")"
    rm "$work/disk/filler"
    run "$grape" render "$scenes/seed_parabola.json" -o "$work/disk/p.png" --frames 1000
    expect_error "$work/status" "$work/err" "render: 1000 frames need about"
    grep -qF "(use --force to try anyway)" "$work/err" || fail "no --force hint"
    [ "$(ls -A "$work/disk")" = "" ] || fail "files left: $(ls -A "$work/disk")"
    # With --force the run goes ahead, meets the full disk, and removes every frame.
    run "$grape" render "$scenes/seed_parabola.json" -o "$work/disk/p.png" --frames 1000 --force
    expect_error "$work/status" "$work/err" ": no space left on device"
    [ "$(ls -A "$work/disk")" = "" ] || fail "files left: $(ls -A "$work/disk")"
    ;;
interrupted_frames)
    # Ctrl-C (SIGINT) and SIGTERM during --frames: the frames written and the one in progress go.
    for signal in INT TERM; do
        rm -rf "$work/out.d"
        mkdir "$work/out.d"
        "$grape" render "$scenes/seed_parabola.json" -o "$work/out.d/f.png" --frames 100000 --fps 1000 \
            >"$work/out" 2>"$work/err" &
        pid=$!
        i=0
        while [ ! -e "$work/out.d/f-0003.png" ] && [ $i -lt 600 ]; do sleep 0.05; i=$((i + 1)); done
        [ -e "$work/out.d/f-0003.png" ] || { kill -KILL $pid; fail "no frames within 30 s"; }
        kill -$signal $pid
        wait $pid
        status=$?
        echo "SIG$signal: status $status, $(cat "$work/err")"
        # Ended by the signal itself (128 + its number), as shells expect of an interrupted program.
        expected=130
        [ $signal = TERM ] && expected=143
        [ $status = $expected ] || fail "exit status $status after SIG$signal, expected $expected"
        nothing_left "$work/out.d"
    done
    ;;
progress)
    # Progress on stderr when it is a terminal, none otherwise. Progress starts after a second,
    # so a machine that finishes within 2 s shows none and passes.
    command -v script >/dev/null || { echo "no 'script' command to run the tool on a terminal"; exit 77; }
    # on_tty NAME PATTERN COMMAND: runs COMMAND on a pseudo-terminal, expects PATTERN if it took 2 s or more.
    on_tty() {
        # In milliseconds: whole seconds of the clock read 2 for a run of 1.01 s.
        begin=$(date +%s%N)
        script -qec "$3" /dev/null | tr '\r' '\n' >"$work/tty"
        took=$((($(date +%s%N) - begin) / 1000000))
        echo "$1: $took ms"
        if ! grep -E "$2" "$work/tty"; then
            [ $took -lt 2000 ] || fail "no progress shown by $1 in $took ms: $(cat "$work/tty")"
            echo "$1 finished within 2 s: no progress expected"
        fi
    }
    on_tty simulate "^simulate: step [0-9]+ of 4000000 \([0-9]+%\)" "'$grape' simulate parabola --integrator euler --dt 1e-5 --seconds 40"
    grep -q '"method": "implicit"' "$work/tty" || fail "no result: $(cat "$work/tty")"
    run "$grape" simulate parabola --integrator euler --dt 1e-5 --seconds 2
    [ ! -s "$work/err" ] || fail "progress written to a file: $(cat "$work/err")"
    # Frames of a 2000 × 2000 view (a fraction of a second each): progress per frame.
    printf '{"view": {"width": 2000, "height": 2000}, "paths": [{"name": "a", "path": {"kind": "circle", "center": [0, 0], "radius": 100}}]}\n' >"$work/big.json"
    on_tty render "^render: frame [0-9]+ of 8 \([0-9]+%\)" "'$grape' render '$work/big.json' -o '$work/big.png' --frames 8"
    grep -q "wrote 8 frames" "$work/tty" || fail "frames not written: $(cat "$work/tty")"
    ;;
render_to_folder)
    mkdir "$work/taken.png"
    run "$grape" render "$scenes/seed_spiral.json" -o "$work/taken.png"
    expect_error "$work/status" "$work/err" "cannot write $work/taken.png: it is a folder"
    [ -d "$work/taken.png" ] && [ -z "$(ls -A "$work/taken.png")" ] || fail "the folder was changed"
    [ "$(ls -A "$work")" = "err
out
status
taken.png" ] || fail "a temporary is left: $(ls -A "$work")"
    ;;
demo_out_empty)
    run "$grape" demo --out ""
    expect_error "$work/status" "$work/err" "demo: --out must name a folder (got an empty name)"
    ;;
demo_out_file)
    echo text >"$work/file"
    run "$grape" demo --out "$work/file"
    expect_error "$work/status" "$work/err" "demo: --out $work/file: it exists and is not a folder"
    ;;
demo_out_unwritable)
    echo text >"$work/file"
    run "$grape" demo --out "$work/file/sub"
    expect_error "$work/status" "$work/err" "demo: --out $work/file/sub: cannot create the folder"
    ;;
demo_full_disk_new_folder)
    # A failed demo removes the folders it created for --out (and the files in them).
    run_full "$grape" demo --out "$work/new/sub"
    expect_error "$work/status" "$work/err" ": file too large"
    [ ! -e "$work/new" ] || fail "the demo's new folder is left: $(ls -AR "$work/new")"
    ;;
demo_full_disk_keeps_folder)
    # The disk fills half way through the demo's pictures (a 256 KiB tmpfs; the pictures are
    # ~470 KB): the folder keeps exactly what it held, the old gallery.png included.
    if ! mkdir -p "$work/disk" || ! mount -t tmpfs -o size=256k tmpfs "$work/disk" 2>"$work/mount-err"; then
        echo "mounting a tmpfs is not permitted here ($(cat "$work/mount-err")); demo_full_disk_new_folder covers a failed demo"
        exit 77
    fi
    trap 'umount "$work/disk"' EXIT
    echo "mounted a 256 KiB tmpfs at $work/disk: a real full disk"
    echo old >"$work/disk/gallery.png"
    echo mine >"$work/disk/notes.txt"
    run "$grape" demo --out "$work/disk"
    expect_error "$work/status" "$work/err" ": no space left on device"
    [ "$(ls -A "$work/disk")" = "gallery.png
notes.txt" ] || fail "files left or lost: $(ls -A "$work/disk")"
    [ "$(cat "$work/disk/gallery.png")" = old ] || fail "the old gallery.png was replaced"
    ;;
scene_is_folder)
    mkdir "$work/scene.json"
    run "$grape" render "$work/scene.json" -o "$work/x.png"
    expect_error "$work/status" "$work/err" "cannot read $work/scene.json: it is a folder, not a scene file"
    ;;
huge_view)
    # 32768 × 32768 passes the scene's validation but needs 8 GiB of raster: refused up front.
    printf '{"view": {"width": 32768, "height": 32768}, "paths": [{"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [1, 1]}}]}\n' >"$work/big.json"
    run "$grape" render "$work/big.json" -o "$work/big.png"
    expect_error "$work/status" "$work/err" "render: a 32768×32768 picture needs about 8.0 GiB of memory, more than the budget of 1.0 GiB (use --force to render it anyway)"
    [ ! -e "$work/big.png" ] || fail "output written"
    # A vector output of the same view needs no raster: it is written.
    run "$grape" render "$work/big.json" -o "$work/big.svg"
    [ "$(cat "$work/status")" = 0 ] || fail "the SVG was refused: $(cat "$work/err")"
    ;;
long_paths)
    # A circle of 1,592 turns (10000 rad) drawn 200 units wide is 2e6 units of stroke: minutes
    # of cairo's time. Refused with the numbers; a radius of 1e12 fits the view and is drawn.
    printf '{"view": {"width": 640, "height": 480}, "paths": [{"name": "coil", "path": {"kind": "circle", "center": [0, 0], "radius": 100, "start_angle": 0, "end_angle": 10000}}]}\n' >"$work/coil.json"
    run "$grape" render "$work/coil.json" -o "$work/coil.png"
    expect_error "$work/status" "$work/err" "render: the scene's paths are 2.1e+06 units long on the picture (path 'coil': 2.1e+06), more than the budget of 1e+06 units a picture (use --force to render them anyway)"
    [ ! -e "$work/coil.png" ] || fail "output written"
    printf '{"view": {"width": 640, "height": 480}, "paths": [{"name": "arc", "path": {"kind": "circle", "center": [0, 0], "radius": 1e12, "start_angle": 0, "end_angle": 1}}]}\n' >"$work/arc.json"
    run "$grape" render "$work/arc.json" -o "$work/arc.png"
    [ "$(cat "$work/status")" = 0 ] || fail "the huge arc was refused: $(cat "$work/err")"
    ;;
out_of_memory)
    # --force past the budget under a 3 GB address-space limit: memory runs out; the message
    # says what was being built, the exit status is 2, nothing is written.
    printf '{"view": {"width": 32768, "height": 32768}, "paths": [{"name": "a", "path": {"kind": "linear", "start": [0, 0], "end": [1, 1]}}]}\n' >"$work/big.json"
    (ulimit -v 3000000 && exec "$grape" render "$work/big.json" -o "$work/big.png" --force) >"$work/out" 2>"$work/err"
    echo $? >"$work/status"
    expect_error "$work/status" "$work/err" "grape: out of memory while drawing $work/big.png (32768×32768)"
    [ "$(ls -A "$work")" = "big.json
err
out
status" ] || fail "output left: $(ls -A "$work")"
    ;;
*)
    fail "unknown case $case_name"
    ;;
esac
echo "ok"
