# Sourced by scripts/build, scripts/test and scripts/report: the CMake preset they use
# (BEACHBALL_PRESET, `default` unless set: `dev` for warnings as errors, `asan` for CI's
# sanitizer build) and the folder it builds into (CMakePresets.json's binaryDir), and what
# scripts/setup installs for its compiler.
# shellcheck shell=bash
preset="${BEACHBALL_PRESET:-default}"
case "$preset" in
  default | dev) build_dir=build ;;
  *) build_dir="build-$preset" ;;
esac
case "$preset" in
  asan) setup_options=(--sanitizers) ;;
  fuzz) setup_options=(--fuzz) ;;
  *) setup_options=() ;;
esac
