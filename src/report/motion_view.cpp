#include "report/motion_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/text.hpp"
#include "report/backend_style.hpp"
#include "report/gnuplot.hpp"
#include "report/motion_exits.hpp"
#include "report/motion_frames.hpp"
#include "report/motion_geometry.hpp"
#include "report/motion_paint.hpp"
#include "report/motion_panels.hpp"
#include "report/plot_layout.hpp"
#include "study/backend_names.hpp"

namespace bb {

namespace {

using motion::Canvas;
using motion::num;

using motion::kCanvasWidth;
using motion::kMargin;
using motion::Panel;
constexpr double kLegendWidth = 300.0;
constexpr double kTitleHeight = 48.0;
constexpr double kNoteLine = 14.0;  // a line of the title's notes
constexpr double kNoteFont = 11.0;
constexpr double kTimeBarHeight = 46.0;
constexpr double kMinCanvasHeight = 240.0;
constexpr double kMaxCanvasHeight = 640.0;
/// More moving bodies than this, and each backend gets a panel of its own over the
/// reference's ghost: an overlay of every backend's grid is unreadable.
constexpr int kOverlayBodies = 4;
constexpr int kColumns = 3;

using Springs = std::vector<std::pair<std::size_t, std::size_t>>;

int moving_bodies(const Scene& scene, const std::vector<int>& drawn) {
  int n = 0;
  for (int b : drawn) n += !scene.bodies[b].fixed;
  return n;
}

/// The runs with states at report_dt, the reference first.
std::vector<const RunRecord*> drawable_runs(const CaseResults& results) {
  std::vector<const RunRecord*> out;
  for (const RunRecord* r : report_runs(results))
    if (!r->trajectory.states.empty()) out.push_back(r);
  return out;
}

/// The run that frames the view: the reference when it ran to the end, else the longest.
const Trajectory& guide_of(const std::vector<const RunRecord*>& runs) {
  const RunRecord* longest = runs.front();
  for (const RunRecord* r : runs)
    if (r->trajectory.states.size() > longest->trajectory.states.size()) longest = r;
  return runs.front()->trajectory.states.size() == longest->trajectory.states.size()
             ? runs.front()->trajectory
             : longest->trajectory;
}

/// The canvas that frames every run's bodies but those of a run off the guide's scale.
Canvas frame_of(const Scene& scene, const std::vector<const RunRecord*>& runs,
                const std::vector<int>& drawn, const Trajectory& guide) {
  const std::vector<bool> cut = motion::off_frame(scene, runs, drawn, guide);
  std::vector<const Trajectory*> framed;
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (!cut[i]) framed.push_back(&runs[i]->trajectory);
  return motion::fit(scene, framed, drawn, kCanvasWidth, kMinCanvasHeight, kMaxCanvasHeight);
}

/// The title's lines under its note naming each run with a body off the frame, wrapped.
std::vector<std::string> exit_lines(const Scene& scene, const std::vector<const RunRecord*>& runs,
                                    const std::vector<int>& drawn,
                                    const std::vector<motion::FrameExit>& exits, const Canvas& c,
                                    double width) {
  const std::vector<std::string> notes = motion::exit_notes(scene, runs, drawn, exits, c);
  if (notes.empty()) return {};
  std::vector<std::string> lines{"off the frame, marked with an arrow where it left:"};
  for (const std::string& note : notes)
    for (const std::string& line : wrapped(note, width - 2 * kMargin, kNoteFont))
      lines.push_back(line);
  return lines;
}

/// One run's bodies (and springs) moving over `samples`; the paint is the group's.
std::string animated_run(const Scene& scene, const RunRecord& run, const std::vector<int>& drawn,
                         const std::vector<std::size_t>& samples, const Canvas& c,
                         const Springs& springs, double total, double play, double thick) {
  const std::vector<State>& states = run.trajectory.states;
  const std::string timing = fmt::format("dur=\"{:.3f}s\" repeatCount=\"indefinite\"", play);
  std::string out = "<g " + motion::paint(run.backend, thick) + ">\n";
  // A run that stopped early (it diverged) holds its last state and fades.
  const std::size_t last = states.size() - 1;
  if (last < samples.back())
    out += fmt::format(
        "<animate attributeName=\"opacity\" values=\"1;0.3\" keyTimes=\"0;{:.5f}\" "
        "calcMode=\"discrete\" {}/>\n",
        std::min(1.0, run.trajectory.times[last] / total), timing);
  if (!springs.empty()) {
    std::string values;
    for (std::size_t j : samples)
      values += (values.empty() ? "" : ";") +
                motion::springs_path(scene, states[std::min(j, last)], springs, c);
    out += fmt::format(
        "<path fill=\"none\" stroke=\"{}\" stroke-width=\"{:.1f}\" stroke-dasharray=\"none\" "
        "opacity=\"0.6\"><animate attributeName=\"d\" values=\"{}\" {}/></path>\n",
        motion::spring_colour(run.backend), 0.8 * thick, values, timing);
  }
  const bool mark = motion::turns(scene);
  for (std::size_t k = 0; k < drawn.size() && k < states.front().size(); ++k) {
    const Body& body = scene.bodies[drawn[k]];
    if (body.fixed) continue;
    std::string cx, cy, d, marks;
    motion::Outline first;
    for (std::size_t f = 0; f < samples.size(); ++f) {
      const motion::Outline o =
          motion::outline(scene, body, states[std::min(samples[f], last)][k], c, mark);
      if (f == 0) first = o;
      const char* sep = f ? ";" : "";
      if (o.circle) {
        cx += sep + num(o.centre.x), cy += sep + num(o.centre.y);
        if (!o.path.empty()) marks += sep + o.path;
      } else {
        d += sep + o.path;
      }
    }
    if (first.circle) {
      out += fmt::format(
          "<circle r=\"{}\"><animate attributeName=\"cx\" values=\"{}\" {}/><animate "
          "attributeName=\"cy\" values=\"{}\" {}/></circle>\n",
          num(first.radius), cx, timing, cy, timing);
      if (!marks.empty())
        out += fmt::format(
            "<path fill=\"none\"><animate attributeName=\"d\" values=\"{}\" {}/></path>\n", marks,
            timing);
    } else {
      out +=
          fmt::format("<path><animate attributeName=\"d\" values=\"{}\" {}/></path>\n", d, timing);
    }
  }
  return out + "</g>\n";
}

/// One run's bodies (and springs) at one state.
std::string still_run(const Scene& scene, const std::string& backend, const State& s,
                      const std::vector<int>& drawn, const Canvas& c, const Springs& springs,
                      double thick) {
  std::string out = "<g " + motion::paint(backend, thick) + ">\n";
  if (!springs.empty())
    out += fmt::format(
        "<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.1f}\" "
        "stroke-dasharray=\"none\" opacity=\"0.6\"/>\n",
        motion::springs_path(scene, s, springs, c), motion::spring_colour(backend), 0.8 * thick);
  for (std::size_t k = 0; k < drawn.size() && k < s.size(); ++k) {
    const Body& body = scene.bodies[drawn[k]];
    if (body.fixed) continue;
    const motion::Outline o = motion::outline(scene, body, s[k], c, motion::turns(scene));
    if (o.circle) {
      out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n", num(o.centre.x),
                         num(o.centre.y), num(o.radius));
      if (!o.path.empty()) out += fmt::format("<path d=\"{}\" fill=\"none\"/>\n", o.path);
    } else {
      out += fmt::format("<path d=\"{}\"/>\n", o.path);
    }
  }
  return out + "</g>\n";
}

/// The state of `t` at the sample nearest `instant`, or its last when it ended before.
const State& state_at(const Trajectory& t, double instant) {
  std::size_t j = 0;
  while (j + 1 < t.times.size() && j + 1 < t.states.size() && t.times[j + 1] <= instant + 1e-9) ++j;
  return t.states[j];
}

/// What the title says of the reference: drawn filled grey, or absent with no answer.
std::string reference_note(const std::vector<const RunRecord*>& runs, bool multiples) {
  if (runs.front()->backend != kReferenceName)
    return "the reference has no answer here: every backend on its own";
  return multiples ? "the reference filled grey, under each backend" : "the reference filled grey";
}

/// The picture's opening, its title and, on a line of its own under it (a long title ran off
/// the picture's edge), what it draws how; then `more` lines, in red (the runs off the frame).
std::string header(double width, double height, const std::string& title, const std::string& note,
                   const std::vector<std::string>& more) {
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" "
      "width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\" "
      "font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n<text "
      "x=\"{2}\" y=\"22\" font-size=\"15\" font-weight=\"bold\">{3}</text>\n"
      "<text x=\"{2}\" y=\"39\" fill=\"#444444\">{4}</text>\n",
      num(width), num(height), num(kMargin), title, note);
  for (std::size_t i = 0; i < more.size(); ++i)
    out += fmt::format("<text x=\"{}\" y=\"{}\" fill=\"#b00000\" font-size=\"{}\">{}</text>\n",
                       num(kMargin), num(39.0 + kNoteLine * (i + 1)), kNoteFont, more[i]);
  return out;
}

}  // namespace

std::vector<double> still_instants(const Scene& scene) {
  return {0.0, scene.duration / 3.0, 2.0 * scene.duration / 3.0, scene.duration};
}

std::string motion_svg(const CaseResults& results, const std::vector<int>& drawn) {
  const Scene& scene = *results.scene;
  const std::vector<const RunRecord*> runs = drawable_runs(results);
  if (runs.empty()) return "";
  const Trajectory& guide = guide_of(runs);
  const Canvas c = frame_of(scene, runs, drawn, guide);
  const bool multiples = moving_bodies(scene, drawn) > kOverlayBodies;
  const double width = 2 * kMargin + kCanvasWidth + (multiples ? 0.0 : kLegendWidth);
  const std::vector<motion::FrameExit> exits = motion::frame_exits(scene, runs, drawn, c);
  const std::vector<std::string> off = exit_lines(scene, runs, drawn, exits, c, width);
  const double top = kTitleHeight + kNoteLine * off.size();

  const Springs all_springs = motion::drawn_springs(scene, drawn);
  const motion::FrameBudget budget =
      motion::frame_budget(scene, drawn, runs.size(), all_springs.size());
  const std::size_t frames = budget.frames, spring_runs = budget.spring_runs;
  // The frames are evenly spread over the samples, so the values need no key times.
  const std::vector<std::size_t> samples = motion::frame_samples(guide.states.size(), frames);
  const double total = guide.times[samples.back()] > 0.0 ? guide.times[samples.back()] : 1.0;
  // Real time, but never shorter than 2 s nor longer than 40 s a loop.
  const double play = std::clamp(total, 2.0, 40.0);

  std::vector<Panel> panels = motion::layout(runs.size(), multiples, c, kColumns, top);
  const double thick = multiples ? c.width / panels.front().width : 1.0;
  double bottom = 0.0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    if (multiples) panels[i].title = motion::run_label(*runs[i]);
    bottom = std::max(bottom, panels[i].y + motion::panel_height(panels[i], c));
  }
  // Tall enough for the legend too: a long one ran off the picture's bottom.
  const double height =
      std::max(bottom + kTimeBarHeight,
               multiples ? 0.0 : motion::legend_bottom(runs.size(), top + 14.0) + kMargin);
  const std::string speed =
      play == total ? "real time" : fmt::format("{:.2g} x real time", total / play);
  std::string svg = header(width, height,
                           fmt::format("{}: the motion at report_dt = {} s", escape_xml(scene.name),
                                       format_dt(scene.report_dt)),
                           speed + "; " + reference_note(runs, multiples), off);
  const motion::MarkTiming timing{total, play, 0.0};
  // In small panels, the reference (when it has an answer) is drawn once, under each.
  const bool ghost = runs.front()->backend == kReferenceName;
  const auto springs_of = [&](std::size_t r) { return r < spring_runs ? all_springs : Springs{}; };
  const std::string backdrop = motion::ground_svg(scene, c) + motion::fixed_svg(scene, c) +
                               motion::wind_svg(scene, c, thick);
  if (!multiples) {
    svg += motion::open_panel(panels.front(), c) + backdrop;
    for (std::size_t r = 0; r < runs.size(); ++r)
      svg += animated_run(scene, *runs[r], drawn, samples, c, springs_of(r), total, play, thick);
    svg += motion::exit_marks_svg(scene, runs, drawn, exits, runs.size(), c, thick, timing);
    svg += "</svg>\n" + motion::legend_svg(runs, 2 * kMargin + kCanvasWidth, top + 14.0);
  } else {
    if (ghost)
      svg +=
          "<defs>\n<g id=\"reference\">\n" +
          animated_run(scene, *runs.front(), drawn, samples, c, springs_of(0), total, play, thick) +
          "</g>\n</defs>\n";
    for (std::size_t r = 0; r < runs.size(); ++r) {
      svg += motion::open_panel(panels[r], c) + backdrop;
      if (ghost) svg += "<use xlink:href=\"#reference\"/>\n";
      if (r > 0 || !ghost)
        svg += animated_run(scene, *runs[r], drawn, samples, c, springs_of(r), total, play, thick);
      svg += motion::exit_marks_svg(scene, runs, drawn, exits, r, c, thick, timing);
      svg += "</svg>\n";
    }
  }

  svg += motion::time_readout(kMargin, kCanvasWidth, bottom + 12.0, total, play);
  return svg;
}

std::string motion_still_svg(const CaseResults& results, const std::vector<int>& drawn,
                             const std::vector<double>& instants) {
  const Scene& scene = *results.scene;
  const std::vector<const RunRecord*> runs = drawable_runs(results);
  if (runs.empty() || instants.empty()) return "";
  const Trajectory& guide = guide_of(runs);
  const Canvas c = frame_of(scene, runs, drawn, guide);
  const bool multiples = moving_bodies(scene, drawn) > kOverlayBodies;
  const double width = 2 * kMargin + kCanvasWidth + (multiples ? 0.0 : kLegendWidth);
  const std::vector<motion::FrameExit> exits = motion::frame_exits(scene, runs, drawn, c);
  const std::vector<std::string> off = exit_lines(scene, runs, drawn, exits, c, width);
  const double top = kTitleHeight + kNoteLine * off.size();
  const Springs all_springs = motion::drawn_springs(scene, drawn);
  // Springs for every run while few, else the reference's only.
  const std::size_t spring_runs = all_springs.size() * runs.size() <= 600 ? runs.size() : 1;
  const auto springs_of = [&](std::size_t r) { return r < spring_runs ? all_springs : Springs{}; };

  // Overlay: a panel per instant, every run in it. Small multiples: a row per run, named
  // above it, a column per instant, each over the reference at that instant.
  const std::size_t count = multiples ? runs.size() * instants.size() : instants.size();
  const double columns = multiples ? static_cast<double>(instants.size()) : 2.0;
  std::vector<Panel> panels = motion::layout(count, true, c, columns, top);
  const double thick = c.width / panels.front().width;
  const std::string backdrop = motion::ground_svg(scene, c) + motion::fixed_svg(scene, c) +
                               motion::wind_svg(scene, c, thick);
  const double row_header = multiples ? motion::kPanelTitle : 0.0;
  std::string row_names;
  double bottom = 0.0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const std::size_t row = i / static_cast<std::size_t>(columns);
    panels[i].y += row_header * (row + 1);
    panels[i].title = fmt::format("t = {:.3g} s", instants[i % instants.size()]);
    if (multiples && i % instants.size() == 0)
      row_names +=
          fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"14\" font-weight=\"bold\">{}</text>\n",
                      num(kMargin), num(panels[i].y - 4.0), motion::run_label(*runs[row]));
    bottom = std::max(bottom, panels[i].y + motion::panel_height(panels[i], c));
  }
  const double height = std::max(
      bottom + kMargin, multiples ? 0.0 : motion::legend_bottom(runs.size(), top + 14.0) + kMargin);
  std::string svg =
      header(width, height,
             fmt::format("{}: the scene at {} instants, report_dt = {} s", escape_xml(scene.name),
                         instants.size(), format_dt(scene.report_dt)),
             reference_note(runs, multiples), off);
  svg += row_names;
  const bool ghost = multiples && runs.front()->backend == kReferenceName;
  if (ghost) {
    svg += "<defs>\n";
    for (std::size_t i = 0; i < instants.size(); ++i)
      svg +=
          fmt::format("<g id=\"reference-{}\">\n", i) +
          still_run(scene, runs.front()->backend, state_at(runs.front()->trajectory, instants[i]),
                    drawn, c, springs_of(0), thick) +
          "</g>\n";
    svg += "</defs>\n";
  }
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const std::size_t at = i % instants.size();
    svg += motion::open_panel(panels[i], c) + backdrop;
    const motion::MarkTiming timing{0.0, 0.0, instants[at]};
    if (multiples) {
      const std::size_t r = i / instants.size();
      if (ghost) svg += fmt::format("<use xlink:href=\"#reference-{}\"/>\n", at);
      if (r > 0 || !ghost)
        svg += still_run(scene, runs[r]->backend, state_at(runs[r]->trajectory, instants[at]),
                         drawn, c, springs_of(r), thick);
      svg += motion::exit_marks_svg(scene, runs, drawn, exits, r, c, thick, timing);
    } else {
      for (std::size_t r = 0; r < runs.size(); ++r)
        svg += still_run(scene, runs[r]->backend, state_at(runs[r]->trajectory, instants[at]),
                         drawn, c, springs_of(r), thick);
      svg += motion::exit_marks_svg(scene, runs, drawn, exits, runs.size(), c, thick, timing);
    }
    svg += "</svg>\n";
  }
  if (!multiples) svg += motion::legend_svg(runs, 2 * kMargin + kCanvasWidth, top + 14.0);
  return svg + "</svg>\n";
}

}  // namespace bb
