// The entry points of the backend plugins the loader's tests build beside the program
// (tests/CMakeLists.txt), one source compiled several ways: a working one, one that crashes
// as a run starts or at a step, one built against another interface version, one without the
// version symbol, one whose backend takes a built-in backend's name, and one of two backends
// (BB_TEST_SECOND). Their backend (falling_backend.cpp) is compiled once for all of them.
#include "plugins/falling_backend.hpp"

namespace {

#ifndef BB_TEST_NAME
#define BB_TEST_NAME "test/falling"
#endif

#if defined(BB_TEST_CRASH_START)
constexpr auto kCrash = bb::test_plugin::Crash::AtStart;
#elif defined(BB_TEST_CRASH_STEP)
constexpr auto kCrash = bb::test_plugin::Crash::AtFourthStep;
#else
constexpr auto kCrash = bb::test_plugin::Crash::Never;
#endif

#ifndef BB_TEST_VERSION_STEP
#define BB_TEST_VERSION_STEP 0
#endif

}  // namespace

// The plugin interface's entry points (seam/plugin_api.hpp), written out: backend number
// `index`, or nullptr past the last.
extern "C" bb::Backend* beachball_create_backend(int index) {
#ifdef BB_TEST_SECOND
  if (index == 1) return bb::test_plugin::falling_backend(BB_TEST_SECOND, kCrash);
#endif
  return index == 0 ? bb::test_plugin::falling_backend(BB_TEST_NAME, kCrash) : nullptr;
}

#ifndef BB_TEST_NO_VERSION
// The interface version it was built with; BB_TEST_VERSION_STEP 1: as if built against the
// next version. Left out (BB_TEST_NO_VERSION): as if built before the interface had one.
extern "C" int beachball_plugin_interface_version() {
  return bb::test_plugin::interface_version() + BB_TEST_VERSION_STEP;
}
#endif
