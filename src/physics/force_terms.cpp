#include "physics/force_terms.hpp"

namespace bb {

// Each term's factory, defined in its own file.
std::unique_ptr<ForceTerm> make_spring_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_drag_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_magnus_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_panel_wind_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_applied_load_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_sail_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_plate_term(const World&, const ForceOptions&);
std::unique_ptr<ForceTerm> make_hull_term(const World&, const ForceOptions&);

namespace {

std::vector<ForceTermEntry>& registry() {
  static std::vector<ForceTermEntry> terms = {
      {"springs (seed section 7)", make_spring_term},
      {"quadratic air drag (seed section 8)", make_drag_term},
      {"Magnus force (seed section 8)", make_magnus_term},
      {"wind on a panel (seed section 8, the falling wall)", make_panel_wind_term},
      {"constant applied force and torque", make_applied_load_term},
      {"a boat's sail in the apparent wind (seed section 9)", make_sail_term},
      {"a panel pushed along its normal by the wind relative to it (seed section 8, Wind)",
       make_plate_term},
      // Last: with no drift the keel cancels every sideways force of the terms above.
      {"a boat's hull in still water, the keel (seed section 9)", make_hull_term},
  };
  return terms;
}

}  // namespace

const std::vector<ForceTermEntry>& force_terms() { return registry(); }

ForceTermRegistration::ForceTermRegistration(ForceTermEntry entry) : name_(entry.name) {
  registry().push_back(std::move(entry));
}

ForceTermRegistration::~ForceTermRegistration() {
  std::erase_if(registry(), [&](const ForceTermEntry& e) { return e.name == name_; });
}

}  // namespace bb
