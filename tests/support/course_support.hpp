// A course backend by integrator name, as the tests build them.
#pragma once

#include <string>

#include "course/course_backend.hpp"

namespace bb::test {

/// course/<integrator> with the ground rule `mirror` and the resolve rule `clamp`.
inline CourseBackend course(const std::string& integrator) {
  return CourseBackend({"course/" + integrator, integrator, "mirror", "clamp"});
}

}  // namespace bb::test
