# Sourced by the scripts that run Windows programs: a Wine prefix of the build's own and one
# persistent wineserver for the whole run.
#   wine_session BUILD_DIR      sets $wine and $wineserver, exports WINEPREFIX (GRAPE_WINEPREFIX,
#                               or BUILD_DIR/wine), stops the server on exit
# Without one persistent server, each program starts a server of its own when the previous one
# has just exited; two tests started together by ctest -j then race to create it, and one of
# them dies at once ("wine client error: recvmsg: Connection reset by peer").
wine_session() {
  local build=$1 start
  wine=$(command -v wine64 || command -v wine || echo /usr/lib/wine/wine64)
  wineserver=$(command -v wineserver || echo /usr/lib/wine/wineserver64)
  # Made once, quietly: no display is needed, and the Mono and Gecko installers (for .NET and
  # HTML programs) are skipped.
  export WINEPREFIX="${GRAPE_WINEPREFIX:-$build/wine}" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
  unset DISPLAY WAYLAND_DISPLAY
  if [[ ! -f "$WINEPREFIX/system.reg" ]]; then
    start=$SECONDS
    "$wine" wineboot -i </dev/null >/dev/null 2>&1
    echo "wine: prefix $WINEPREFIX made in $((SECONDS - start)) s"
  fi
  # `wineserver -p` cannot make a running server persistent (it exits 2), so the server that
  # wineboot left is stopped first.
  "$wineserver" -k 2>/dev/null || true
  "$wineserver" -w
  "$wineserver" -p </dev/null >/dev/null 2>&1
  trap '"$wineserver" -k 2>/dev/null || true' EXIT
  # Wine's background services started now, detached from any output: started by a test's
  # program, they would inherit its stdout and keep the pipe ctest or CMake reads open.
  "$wine" wineboot </dev/null >/dev/null 2>&1
}
