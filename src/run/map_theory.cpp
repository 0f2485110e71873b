#include "run/map_theory.hpp"

#include "run/stability.hpp"

namespace bb {

const std::vector<MapTheory>& map_theories() {
  static const std::vector<MapTheory> theories = {
      // Seed section 7: the course integrator's largest stable step (stability_theory.hpp),
      // as the stability search's theory column states it.
      {"dt", "theory's largest stable step",
       "the course theory's largest stable step for the backend's integrator (stable on the "
       "side of the smaller steps)",
       "Where one axis is the step and the course text's theory covers a backend's integrator, "
       "the dashed line is the theory's largest stable step at each value of the other (the "
       "stability search's theory column, computed at that point). A run is judged over the case's "
       "duration only: "
       "growth too slow to show in that time (explicit Euler at the smallest steps) is ok on the "
       "map though the theory calls it unstable.",
       [](const Scene& point, const std::string& backend) { return theory_for(point, backend); }},
  };
  return theories;
}

}  // namespace bb
