# Sourced by the tool_*.sh case scripts called as SCRIPT CASE GRAPE WORKDIR [SCENES_DIR]:
# sets case_name, grape, work (a fresh WORKDIR/CASE) and scenes, and defines fail.
case_name=$1
grape=$2
work=$3/$case_name
scenes=${4:-}
rm -rf "$work"
mkdir -p "$work"

fail() {
    echo "FAIL: $*"
    exit 1
}
