// libFuzzer target: any bytes given to the case loader either load or raise a CaseError.
// Anything else (another exception, a crash, a sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "run/case_loading.hpp"
#include "study/case_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    bb::parse_case(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
  } catch (const bb::CaseError&) {
    // Bad input, told as such: the expected outcome for most inputs.
  }
  return 0;
}
