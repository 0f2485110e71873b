# Precompiled headers: the library headers nearly every source includes (Eigen through the
# headers of model/, the standard library) compiled once per target, so each of its
# sources (or unity sources) loads them instead of parsing them again. Off with
# -DBEACHBALL_PCH=OFF (a source that forgot an include still compiles with them on).
#
#   bb_precompile_heavy_headers(target... [HEADERS header...])
#
# HEADERS adds headers to the common set for these targets (GoogleTest for the tests, fmt
# for the targets that link it); a header must be one the target can include. A target
# compiled in a single compiler run gets none.
set(BB_COMMON_PCH_HEADERS
    <Eigen/Geometry> <algorithm> <cmath> <filesystem> <functional> <map> <memory> <optional>
    <set> <sstream> <string> <vector>)

function(bb_precompile_heavy_headers)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "" "HEADERS")
  if(NOT BEACHBALL_PCH)
    return()
  endif()
  foreach(target IN LISTS arg_UNPARSED_ARGUMENTS)
    # A target compiled in one compiler run (one source, or one unity batch) would parse
    # the headers once either way: precompiling them first only adds a run.
    get_target_property(sources ${target} SOURCES)
    get_target_property(unity ${target} UNITY_BUILD)
    list(LENGTH sources runs)
    if(unity)
      set(batch 8)
      if(CMAKE_UNITY_BUILD_BATCH_SIZE)
        set(batch ${CMAKE_UNITY_BUILD_BATCH_SIZE})
      endif()
      math(EXPR runs "(${runs} + ${batch} - 1) / ${batch}")
    endif()
    if(runs GREATER 1)
      target_precompile_headers(${target} PRIVATE ${BB_COMMON_PCH_HEADERS} ${arg_HEADERS})
    endif()
  endforeach()
endfunction()
