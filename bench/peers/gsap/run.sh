#!/bin/sh
# Runs the GSAP peer of bench_anim: installs gsap (package.json) into a scratch folder, never
# into the repository, then runs bench.js there. Arguments pass through, e.g.
#   bench/peers/gsap/run.sh tween --n 1000,100000
set -eu
here=$(cd "$(dirname "$0")" && pwd)
scratch=${GSAP_SCRATCH:-${TMPDIR:-/tmp}/grape-gsap-peer}
mkdir -p "$scratch"
cp "$here/package.json" "$here/bench.js" "$here/timing.js" "$scratch/"
(cd "$scratch" && npm install --no-audit --no-fund --loglevel=error >/dev/null)
exec node --expose-gc --max-old-space-size=12288 "$scratch/bench.js" "$@"
