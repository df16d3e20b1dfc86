# Sourced by scripts/run-tests and scripts/run-demo: the configuration of build/, one for both so
# that either command after the other reuses what is built. The build that is quickest from a
# clean tree: the libraries and the tool as unity builds (a unity build is also what a game's
# project gets by default), -O2 without debug information (-g costs about a third of the compile
# time; g++ 12 at -O3 gives false-positive -Wrestrict and -Wmaybe-uninitialized, errors here).
# The fuzz build (scripts/run-fuzz) compiles every module file by file, so each file still
# compiles on its own. For a debugger, use the `dev` preset (RelWithDebInfo, file by file).
main_build_args=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" -DGRAPE_UNITY_BUILD=ON
                 -DGRAPE_WERROR=ON)
