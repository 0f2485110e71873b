#include "report/motion_exits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "report/motion_paint.hpp"
#include "report/off_scale.hpp"
#include "report/plot_layout.hpp"
#include "report/xml_text.hpp"

namespace bb::motion {

namespace {

/// The most arrows a run gets in a panel (a grid that blows up sends out every particle);
/// the title counts them all.
constexpr std::size_t kArrowsPerRun = 12;

bool inside(const Canvas& c, Point2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && p.x >= 0.0 && p.x <= c.width && p.y >= 0.0 &&
         p.y <= c.height;
}

/// Where the ray from `from` (inside the canvas) along `dir` meets the canvas's edge.
Point2 to_edge(const Canvas& c, Point2 from, Point2 dir) {
  const auto along = [](double at, double d, double hi) {
    return d > 0.0 ? (hi - at) / d : d < 0.0 ? -at / d : std::numeric_limits<double>::infinity();
  };
  const double t =
      std::max(0.0, std::min(along(from.x, dir.x, c.width), along(from.y, dir.y, c.height)));
  return {from.x + t * dir.x, from.y + t * dir.y};
}

/// The body's position as the note gives it: (x, y) in 2D, (x, y, z) in 3D.
std::string where(const Scene& scene, const Vec3& p) {
  return scene.dims == 2 ? fmt::format("({:.3g}, {:.3g})", p.x(), p.y())
                         : fmt::format("({:.3g}, {:.3g}, {:.3g})", p.x(), p.y(), p.z());
}

}  // namespace

std::vector<bool> off_frame(const Scene& scene, const std::vector<const RunRecord*>& runs,
                            const std::vector<int>& drawn, const Trajectory& guide) {
  Extent gx, gy;
  for (const State& s : guide.states)
    for (std::size_t k = 0; k < drawn.size() && k < s.size(); ++k) {
      const Point2 p = project(scene, s[k].position);
      gx.add(p.x), gy.add(p.y);
    }
  std::vector<bool> out(runs.size(), false);
  if (gx.empty() || gy.empty()) return out;
  std::vector<double> reach, typical;
  for (const RunRecord* r : runs) {
    double most = 0.0;
    for (const State& s : r->trajectory.states)
      for (std::size_t k = 0; k < drawn.size() && k < s.size(); ++k) {
        const Point2 p = project(scene, s[k].position);
        most = std::max({most, gx.beyond(p.x), gy.beyond(p.y)});
      }
    reach.push_back(most);
    if (r->status != RunStatus::Diverged) typical.push_back(most);
  }
  // A diverged run's numbers are not the scene's (cloth_stiff: seven of fifteen runs blow
  // up): it never sets the frame, nor the typical run's reach. Never less than a metre
  // across, as the canvas is.
  const double limit = off_scale_limit(typical, std::max(gx.span(), gy.span()), 1.0);
  for (std::size_t i = 0; i < runs.size(); ++i)
    out[i] = runs[i]->status == RunStatus::Diverged || reach[i] > limit;
  return out;
}

std::vector<FrameExit> frame_exits(const Scene& scene, const std::vector<const RunRecord*>& runs,
                                   const std::vector<int>& drawn, const Canvas& c) {
  std::vector<FrameExit> out;
  const Point2 centre{c.width / 2, c.height / 2};
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const Trajectory& t = runs[r]->trajectory;
    for (std::size_t k = 0; k < drawn.size(); ++k) {
      if (scene.bodies[drawn[k]].fixed) continue;
      // The last sample inside, then the first outside: the body left between them.
      std::optional<Point2> last_in;
      for (std::size_t j = 0; j < t.states.size() && j < t.times.size(); ++j) {
        if (k >= t.states[j].size()) break;
        const Point2 p = c.px(project(scene, t.states[j][k].position));
        if (inside(c, p)) {
          last_in = p;
          continue;
        }
        const Point2 from = last_in.value_or(centre);
        const bool finite = std::isfinite(p.x) && std::isfinite(p.y);
        // Towards where it went; a body gone to NaN points on from the centre past its last.
        Point2 dir = finite ? Point2{p.x - from.x, p.y - from.y}
                            : Point2{from.x - centre.x, from.y - centre.y};
        const double norm = std::hypot(dir.x, dir.y);
        dir = norm > 0.0 ? Point2{dir.x / norm, dir.y / norm} : Point2{1.0, 0.0};
        out.push_back({r, k, t.times[j], to_edge(c, from, dir), dir});
        break;
      }
    }
  }
  return out;
}

std::string exit_marks_svg(const Scene& scene, const std::vector<const RunRecord*>& runs,
                           const std::vector<int>& drawn, const std::vector<FrameExit>& exits,
                           std::size_t run, const Canvas& c, double thick, MarkTiming timing) {
  std::string out;
  // Per run, its earliest exit is labelled and the arrows drawn are counted.
  std::vector<const FrameExit*> first(runs.size(), nullptr);
  std::vector<std::size_t> drawn_arrows(runs.size(), 0);
  for (const FrameExit& e : exits)
    if (first[e.run] == nullptr || e.time < first[e.run]->time) first[e.run] = &e;
  for (const FrameExit& e : exits) {
    if (run < runs.size() && e.run != run) continue;
    if (timing.play <= 0.0 && e.time > timing.instant + 1e-9) continue;
    if (drawn_arrows[e.run]++ >= kArrowsPerRun) continue;
    const std::string colour = spring_colour(runs[e.run]->backend);
    const Point2 d = e.direction;
    // An arrow pointing out of the frame, its tip just inside the edge.
    const Point2 tip{e.edge.x - 3 * thick * d.x, e.edge.y - 3 * thick * d.y};
    const Point2 tail{tip.x - 24 * thick * d.x, tip.y - 24 * thick * d.y};
    const auto barb = [&](double turn) {
      const double ca = std::cos(turn), sa = std::sin(turn);
      return Point2{tip.x - 9 * thick * (ca * d.x - sa * d.y),
                    tip.y - 9 * thick * (sa * d.x + ca * d.y)};
    };
    const Point2 b1 = barb(0.45), b2 = barb(-0.45);
    // The name and time beyond the arrow's tail, kept inside the frame.
    const char* anchor = d.x > 0.4 ? "end" : d.x < -0.4 ? "start" : "middle";
    const double font = 11 * thick;
    const std::string text =
        fmt::format("{} left at {:.3g} s", scene.bodies[drawn[e.slot]].name, e.time);
    // The text's width, about (plot_layout.hpp's bound), and how much of it lies left of x.
    const double wide = text_width_bound(text, font);
    const double left_of = anchor[0] == 'e' ? wide : anchor[0] == 'm' ? wide / 2 : 0.0;
    double x = tail.x - 3 * thick * d.x, y = tail.y - 3 * thick * d.y + (d.y < -0.4 ? font : 0);
    x = std::max(4 * thick + left_of, std::min(x, c.width - 4 * thick - (wide - left_of)));
    y = std::clamp(y, font + 2 * thick, c.height - 4 * thick);
    const std::string appear =
        timing.play > 0.0 && e.time > 0.0
            ? fmt::format(
                  "<animate attributeName=\"opacity\" values=\"0;1\" keyTimes=\"0;{:.5f}\" "
                  "calcMode=\"discrete\" dur=\"{:.3f}s\" repeatCount=\"indefinite\"/>",
                  std::clamp(e.time / timing.total, 1e-5, 1.0), timing.play)
            : "";
    const std::string label =
        &e == first[e.run]
            ? fmt::format(
                  "<text x=\"{}\" y=\"{}\" fill=\"{}\" stroke=\"none\" font-size=\"{:.1f}\" "
                  "text-anchor=\"{}\">{}</text>",
                  num(x), num(y), colour, font, anchor, escape_xml(text))
            : "";
    out += fmt::format(
        "<g class=\"frame-exit\" stroke=\"{}\" stroke-width=\"{:.1f}\" fill=\"none\">{}"
        "<path d=\"M{} {} L{} {} M{} {} L{} {} L{} {}\"/>{}</g>\n",
        colour, 2 * thick, appear, num(tail.x), num(tail.y), num(tip.x), num(tip.y), num(b1.x),
        num(b1.y), num(tip.x), num(tip.y), num(b2.x), num(b2.y), label);
  }
  return out;
}

std::vector<std::string> exit_notes(const Scene& scene, const std::vector<const RunRecord*>& runs,
                                    const std::vector<int>& drawn,
                                    const std::vector<FrameExit>& exits, const Canvas& c) {
  std::vector<std::string> out;
  const Point2 middle{c.x0 + c.width / c.scale / 2, c.y1 - c.height / c.scale / 2};
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const FrameExit* first = nullptr;
    std::size_t bodies = 0;
    for (const FrameExit& e : exits)
      if (e.run == r) {
        ++bodies;
        if (first == nullptr || e.time < first->time) first = &e;
      }
    if (first == nullptr) continue;
    // The farthest any of its bodies that left goes, and when one first went to NaN.
    double far = -1.0, nan_at = -1.0;
    Vec3 farthest = Vec3::Zero();
    const Trajectory& t = runs[r]->trajectory;
    for (const FrameExit& e : exits) {
      if (e.run != r) continue;
      for (std::size_t j = 0; j < t.states.size() && j < t.times.size(); ++j) {
        const Vec3& p = t.states[j][e.slot].position;
        if (!p.allFinite()) {
          if (nan_at < 0.0 || t.times[j] < nan_at) nan_at = t.times[j];
          continue;
        }
        const Point2 q = project(scene, p);
        const double d = std::hypot(q.x - middle.x, q.y - middle.y);
        if (d > far) far = d, farthest = p;
      }
    }
    std::string line = fmt::format("{}: {} left at t = {:.3g} s", run_label(*runs[r]),
                                   escape_xml(scene.bodies[drawn[first->slot]].name), first->time);
    if (bodies > 1)
      line += fmt::format(" ({} more {})", bodies - 1, bodies > 2 ? "bodies" : "body");
    if (far >= 0.0) line += ", reaches " + where(scene, farthest) + " m";
    if (nan_at >= 0.0) line += fmt::format(", not a number from t = {:.3g} s", nan_at);
    out.push_back(line);
  }
  return out;
}

}  // namespace bb::motion
