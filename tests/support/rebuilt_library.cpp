// One more translation unit in the second build of libbb_physics.so (tests/CMakeLists.txt):
// it gives that library other bytes and changes nothing it computes.
extern "C" int beachball_rebuilt_for_a_test() {
  return 1;
}
