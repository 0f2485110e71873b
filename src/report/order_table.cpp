#include "report/order_table.hpp"

#include <fmt/format.h>

namespace bb {

std::string local_slopes_text(const OrderFit& fit) {
  std::string out;
  bool inside = false;
  for (const LocalSlope& s : fit.local_slopes) {
    if (!out.empty()) out += " ";
    if (s.in_fit && !inside) out += "[";
    if (!s.in_fit && inside) out.insert(out.size() - 1, "]");
    inside = s.in_fit;
    out += fmt::format("{:.2f}", s.slope);
  }
  if (inside) out += "]";
  return out.empty() ? "-" : out;
}

Table order_table(const CaseResults& results) {
  Table t;
  t.headers = {"backend", "order", "local slopes, smallest dt first", "points fitted",
               "why no order"};
  t.right_aligned = {false, true, false, true, false};
  for (const auto& [name, fit] : results.order_fits)
    t.rows.push_back({name, fit.slope ? fmt::format("{:.2f}", *fit.slope) : "none",
                      local_slopes_text(fit), std::to_string(fit.used),
                      fit.reason.empty() ? "-" : fit.reason});
  return t;
}

std::string order_markdown(const CaseResults& results) {
  if (results.order_fits.empty()) return "";
  return "\n### Order of convergence\n\n"
         "The order column is the least-squares slope of log position_max against log dt over "
         "the asymptotic range only: from the smallest dt whose error lies above its rounding "
         "floor and below saturation, the neighbouring steps upwards whose local slopes agree "
         "(within 0.25, or 15 percent of their mean), at least three of them, with a slope of "
         "at least 0.5. The rounding floor is ten times the reference's self-check, or the "
         "rounding a run can pile up on the largest position (machine epsilon, float's for an "
         "engine built in single precision, times that position times the run's number of "
         "steps, at least 100 of them), whichever is larger. An error at or above a tenth of "
         "the motion's scale (the farthest any body of the reference moves from its start, or "
         "the largest body's size) has saturated. Elsewhere there is no order, and the table "
         "says why: rounding, saturated, not asymptotic (local slopes that disagree), not "
         "converging, or too few points. The local slopes in brackets are the ones fitted.\n\n" +
         render_markdown(order_table(results));
}

}  // namespace bb
