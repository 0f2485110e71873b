# Sourced by scripts/build, scripts/test and scripts/report: the CMake preset they use
# (BEACHBALL_PRESET, `default` unless set: `dev` for warnings as errors, `asan` for CI's
# sanitizer build) and the folder it builds into (CMakePresets.json's binaryDir).
# shellcheck shell=bash
preset="${BEACHBALL_PRESET:-default}"
case "$preset" in
  default | dev) build_dir=build ;;
  *) build_dir="build-$preset" ;;
esac
