#include "report/motion_paint.hpp"

#include <fmt/format.h>

#include "report/backend_style.hpp"
#include "report/motion_geometry.hpp"

namespace bb::motion {

/// Stroke and fill of a run: the reference filled grey under the others, the course
/// methods in solid lines, the engines dashed; `thick` scales the lines (small panels).
std::string paint(const std::string& backend, double thick) {
  const BackendStyle s = backend_style(backend);
  if (s.kind == LineKind::Reference)
    return fmt::format(
        "fill=\"#cfcfcf\" fill-opacity=\"0.85\" stroke=\"#000000\" stroke-width=\"{:.1f}\"",
        1.5 * thick);
  return fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"{:.1f}\"{}", s.colour, 2.0 * thick,
                     s.kind == LineKind::Engine
                         ? fmt::format(" stroke-dasharray=\"{:.0f} {:.0f}\"", 6 * thick, 3 * thick)
                         : "");
}

std::string spring_colour(const std::string& backend) {
  const BackendStyle s = backend_style(backend);
  return s.kind == LineKind::Reference ? "#555555" : s.colour;
}

std::string run_label(const RunRecord& run) {
  return escape_xml(run.backend +
                    (run.status == RunStatus::Ok ? "" : " (" + status_name(run.status) + ")"));
}

/// A legend entry per run.
std::string legend_svg(const std::vector<const RunRecord*>& runs, double x, double y) {
  std::string out = fmt::format(
      "<text x=\"{}\" y=\"{}\" font-weight=\"bold\">at report_dt</text>\n", num(x), num(y));
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const double row = y + 20.0 * (i + 1);
    out += fmt::format(
        "<circle cx=\"{}\" cy=\"{}\" r=\"6\" {}/>\n<text x=\"{}\" y=\"{}\">{}</text>\n", num(x + 7),
        num(row - 4), paint(runs[i]->backend, 1.0), num(x + 20), num(row), run_label(*runs[i]));
  }
  return out;
}

double legend_bottom(std::size_t runs, double y) {
  return y + 20.0 * static_cast<double>(runs) + 5.0;
}

}  // namespace bb::motion
