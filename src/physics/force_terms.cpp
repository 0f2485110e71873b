#include "physics/force_terms.hpp"

namespace bb {

// Each term's factory, defined in its own file.
std::unique_ptr<ForceTerm> make_spring_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_drag_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_magnus_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_panel_wind_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_applied_load_term(const World&, const ForceOptions&);

const std::vector<ForceTermEntry>& force_terms() {
  static const std::vector<ForceTermEntry> terms = {
      {"springs (seed section 7)", make_spring_term},
      {"quadratic air drag (seed section 8)", make_drag_term},
      {"Magnus force (seed section 8)", make_magnus_term},
      {"wind on a panel (seed section 8, the falling wall)", make_panel_wind_term},
      {"constant applied force and torque", make_applied_load_term},
  };
  return terms;
}

}  // namespace bb
