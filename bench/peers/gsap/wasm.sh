#!/bin/sh
# GSAP and grape.wasm side by side (wasm.js): installs gsap (package.json) and the local
# grape-wasm package (web/, built by scripts/build-web) into a scratch folder, never into the
# repository, then runs wasm.js there. Arguments pass through, e.g.
#   bench/peers/gsap/wasm.sh --n 100000 --modes arc-length
set -eu
here=$(cd "$(dirname "$0")" && pwd)
web=$(cd "$here/../../../web" && pwd)
[ -f "$web/dist/grape-node.wasm" ] || { echo "wasm.sh: build grape.wasm first (scripts/build-web)" >&2; exit 1; }
scratch=${GSAP_SCRATCH:-${TMPDIR:-/tmp}/grape-gsap-wasm}
mkdir -p "$scratch"
cp "$here/package.json" "$here/wasm.js" "$here/timing.js" "$scratch/"
(cd "$scratch" && npm install --no-audit --no-fund --loglevel=error "$web" >/dev/null && npm install --no-audit --no-fund --loglevel=error >/dev/null)
exec node --expose-gc --max-old-space-size=12288 "$scratch/wasm.js" "$@"
