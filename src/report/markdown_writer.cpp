#include "report/markdown_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "report/claims_page.hpp"
#include "report/cost_noise.hpp"
#include "report/format.hpp"
#include "report/map_page.hpp"
#include "report/markdown_text.hpp"
#include "report/order_table.hpp"
#include "report/scene_description.hpp"
#include "report/summary_tables.hpp"
#include "report/sweep_page.hpp"
#include "report/work_precision.hpp"
#include "run/cost.hpp"

namespace bb {

namespace {

std::string settings_text(const Settings& settings) {
  std::string out;
  for (const auto& [key, value] : settings) {
    std::string v = std::visit(
        [](const auto& x) -> std::string {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_same_v<T, bool>)
            return x ? "true" : "false";
          else if constexpr (std::is_same_v<T, double>)
            return fmt::format("{:g}", x);
          else
            return x;
        },
        value);
    out += (out.empty() ? "" : ", ") + key + " = " + v;
  }
  return out;
}

}  // namespace

namespace {

/// The title, the case's name, section and file, and the scene described.
std::string header(const CaseResults& results) {
  const Scene& scene = *results.scene;
  // The case's own text goes through markdown_text: a title cannot end the heading or add
  // HTML. The name needs nothing (the loader allows a-z, 0-9 and _ only).
  std::string out = fmt::format("# {}\n\nCase `{}`", markdown_text(scene.title), scene.name);
  if (!scene.seed.empty())
    out += fmt::format(", from section \"{}\" of the course text", markdown_text(scene.seed));
  out += fmt::format(". Case file: `{}`.\n\n## Scene\n\n{}\n", markdown_text(scene.file),
                     describe_scene(scene));
  return out;
}

/// The summary table at report_dt, what its errors are against, its notes and the order table.
std::string results_section(const CaseResults& results) {
  const Scene& scene = *results.scene;
  std::string out;
  out += fmt::format("## Results at report_dt = {} s\n\n", format_dt(scene.report_dt));
  // Say first what the errors are measured against when it is not the reference.
  if (results.reference_run.status != RunStatus::Ok)
    out +=
        markdown_text("The reference has no answer for this case: " + results.reference_run.reason +
                      ". Each backend's errors below are against its own run at the finest "
                      "dt of the sweep (self-consistency: the reference's fallback, "
                      "docs/design.md): they show "
                      "how far a step is from converged, not how far from the truth; the "
                      "finest run has none.") +
        "\n\n";
  out +=
      "Errors are against the reference at every sample, worst body (named where there are "
      "several; each body's are folded below the table): pos max, pos rms and "
      "pos final are position_max, position_rms and position_final (m), vel max is "
      "velocity_max (m/s), energy max is energy_max (relative to the initial energy, at "
      "least 1 J). Observables show the value and, in brackets, its difference from the "
      "reference; for terminal_velocity, on every row, from the terminal speed sqrt(2 m g / "
      "(rho Cd A)) computed from the scene.\n\n";
  out += render_markdown(summary_table(results, scene.report_dt));
  // Which part of the scene is wrong: every body's errors, folded.
  if (scene.bodies.size() > 1)
    if (const PerBodyErrors each = per_body_errors(results, scene.report_dt);
        !each.table.rows.empty())
      out += fmt::format(
          "\n<details><summary>Each body's errors ({})</summary>\n\n{}\n</details>\n",
          each.cut ? fmt::format("each backend's {} worst of the {} bodies, worst first; the "
                                 "JSON has every body's",
                                 kPerBodyRows, scene.bodies.size())
                   : std::string("worst first"),
          render_markdown(each.table));
  const auto notes = run_notes(results, scene.report_dt);
  if (!notes.empty()) {
    out += "\n";
    for (const std::string& n : notes) out += "- " + markdown_text(n) + "\n";
  }
  if (const std::string busy = cost_noise_warning(results); !busy.empty())
    out += "\n" + markdown_text(busy) + "\n";
  if (const std::string kept = kept_costs_note({results}); !kept.empty())
    out += "\n" + markdown_text(kept) + "\n";
  out += order_markdown(results);
  return out;
}

/// The motion view, the trajectories, speed and energy, and the distance from the reference.
std::string motion_sections(const CaseResults& results, const PlotFiles& plots) {
  const Scene& scene = *results.scene;
  std::string out;
  if (!plots.motion.empty()) {
    out += fmt::format("\n## The motion at report_dt = {} s\n\n", format_dt(scene.report_dt));
    out +=
        "Every backend's bodies over the reference's (filled grey), playing in a loop; the "
        "[still](" +
        plots.still + ") shows four instants for print.\n\n![the motion](" + plots.motion + ")\n";
  }
  if (!plots.trajectory.empty() || !plots.energy.empty()) {
    out += fmt::format("\n## Trajectories and energy at report_dt = {} s\n\n",
                       format_dt(scene.report_dt));
    out +=
        "The reference is the thick black line; a method that drifts, gains energy or sinks "
        "leaves it. Each moving body is drawn as its path (y against x) where it moves both "
        "ways in the plane, else as the coordinate that moves most against time; bodies that a "
        "claim of the case compares share one panel and one scale, each named where the "
        "reference's curve ends. The energy counts every spring's; a run far off the others' "
        "scale is cut at the plot's edge, and its title says which and how far it goes.\n\n";
    if (!plots.trajectory.empty()) out += "![trajectories](" + plots.trajectory + ")\n\n";
    if (!plots.speed.empty()) out += "![speed](" + plots.speed + ")\n\n";
    if (!plots.energy.empty()) out += "![energy](" + plots.energy + ")\n";
  }
  if (!plots.error.empty()) {
    out += fmt::format("\n## Distance from the reference at report_dt = {} s\n\n",
                       format_dt(scene.report_dt));
    out +=
        "Each backend's largest position distance from the reference, over its bodies, against "
        "time on a log scale: where and when each method parts from the reference. After a "
        "bounce this distance is dominated by the bounce's timing (a ball that turns a step "
        "late is far from the reference while both fly); the contact-time and apex observables "
        "measure the bounce itself.\n\n![distance from the reference](" +
        plots.error + ")\n";
  }
  return out;
}

/// Around the stop, and the rotation.
std::string stop_and_rotation_sections(const CaseResults& results, const PlotFiles& plots) {
  const Scene& scene = *results.scene;
  std::string out;
  if (!plots.stop.empty()) {
    out += fmt::format("\n## Around the stop at report_dt = {} s\n\n", format_dt(scene.report_dt));
    out +=
        "For each sliding body: how far it has slid and its velocity along its direction of "
        "sliding (its first push, else downhill), from half a second before the reference "
        "stops it to the end of the run. A method that carries the velocity past zero turns "
        "back and crawls here; one that holds the body draws a flat line.\n\n![around the "
        "stop](" +
        plots.stop + ")\n";
  }

  if (!plots.rotation.empty()) {
    out += fmt::format("\n## Rotation at report_dt = {} s\n\n", format_dt(scene.report_dt));
    out += scene.dims == 2
               ? "For each turning body: its angle about z (unwrapped) and its angular velocity, "
                 "every backend over the reference.\n\n"
               : "For each turning body: how far the body axis it first spun about has tilted "
                 "from where it started (a tennis-racket flip swings it to 180 degrees and "
                 "back), and its spin about that axis in the body frame (which changes sign at "
                 "each flip), every backend over the reference.\n\n";
    out += "![rotation](" + plots.rotation + ")\n";
  }
  return out;
}

/// The claims the case checks, with every backend's verdict, and the sweep.
std::string claims_section(const CaseResults& results, const PlotFiles& plots) {
  std::string out;
  const Table claims = case_claims_table(results);
  // Every page has the section: a case without claims says so, so that a reader looking for
  // the claims finds that there are none rather than wondering where they went.
  if (claims.rows.empty())
    out +=
        "\n## Claims\n\nNo claim of the course text is tested on this case; the [claims "
        "ledger](claims.md) lists the claims every case of a report tests.\n";
  else
    out +=
        "\n## Claims\n\nThe sentences of the course text this case checks, each with the "
        "words it quotes (or marked as the case's own), and every backend's verdict over the dt "
        "sweep with the two numbers compared at report_dt; a report's [claims "
        "ledger](claims.md) has every case's.\n\n" +
        render_markdown(claims);

  out += sweep_markdown(results, plots.sweep);
  out += map_markdown(results, plots.map);
  return out;
}

/// Error against cost, and the cheapest step that reaches the target.
std::string work_precision_section(const CaseResults& results, const PlotFiles& plots) {
  const Scene& scene = *results.scene;
  std::string out;
  out += "\n## Work precision\n\n";
  out +=
      "Error against the cost of computing one simulated second, one marker per dt of the "
      "sweep; lower and further left is better. The dashed line is the reference's own "
      "error (its self-check), below which differences are noise.\n\n";
  for (const auto& [metric, file] : plots.work_precision)
    out += "![work-precision " + metric + "](" + file + ")\n\n";
  const std::string& first = scene.report.metrics.front();
  out += fmt::format("Cheapest step of the sweep that keeps {} within {:g}:\n\n", first,
                     scene.report.target);
  out += render_markdown(cheapest_step_table(results, first, scene.report.target));
  if (!plots.note.empty()) out += "\n" + markdown_text(plots.note) + "\n";
  return out;
}

/// The largest stable steps, how they were searched, and the theory beside them.
std::string stability_section(const CaseResults& results) {
  const Scene& scene = *results.scene;
  std::string out;
  if (!results.stability.empty()) {
    out += fmt::format(
        "\n## Stability\n\nThe largest stable step per backend, searched in log dt between "
        "{:g} s and {:g} s: bisection to 0.1 percent, then steps at 0.9, 0.75, 0.5 and 0.25 of "
        "the one found are probed, and wherever neighbouring steps disagree the search narrows "
        "down between them (to 1 percent above the first threshold). Where stability is not "
        "monotone in dt the result lists the bands, and the largest stable step is the largest "
        "with every step tried below it stable. Stable means bounded over the {:g} s of the "
        "case: no divergence, and an energy whose rise above its start neither compounds (in "
        "each of the run's last two quarters it grows more than {:g} times faster than steady "
        "drift would, without slowing down as any power of time does) nor runs away (from "
        "within the scene's energy scale to more than ten times it, even if the motion's "
        "nonlinearity then caps it). Drift that adds (explicit Euler's energy on a parabola) "
        "and a large swing that repeats itself are stable, and the result says when the "
        "largest stable step drifts. Theory, where the scene allows one, is derived from the "
        "case's own numbers.\n\n",
        scene.stability.dt_min, scene.stability.dt_max, scene.duration,
        scene.stability.growth_factor);
    out += render_markdown(stability_table(results));
    // How to read the measured limits beside the theory, once per distinct note.
    std::vector<std::string> notes;
    for (const StabilityResult& r : results.stability)
      if (!r.theory_note.empty() &&
          std::find(notes.begin(), notes.end(), r.theory_note) == notes.end())
        notes.push_back(r.theory_note);
    for (const std::string& note : notes) out += "\n" + markdown_text(note) + "\n";
  }
  return out;
}

/// Every run of the sweep, and the gates.
std::string every_dt_section(const CaseResults& results) {
  const Scene& scene = *results.scene;
  std::string out;
  out += "\n## Every dt\n\n";
  if (!scene.observes.empty())
    out +=
        "Every run of the sweep, with each observable and, in brackets, its difference from the "
        "reference: a course claim that holds at one step and fails at another shows here.\n\n";
  out += render_markdown(sweep_table(results));
  out += "\n## Gates\n\n" + (results.gates.empty()
                                 ? std::string("No gates: the case sets no [[gate]].\n")
                                 : render_markdown(gate_table(results)));
  return out;
}

/// How the reference was solved and checked, how cost was timed, and the versions.
std::string reference_section(const CaseResults& results) {
  std::string out;
  const ReferenceInfo& ref = results.reference;
  out += fmt::format(
      "\n## Reference and cost\n\n- reference: {}, absolute and relative tolerance {:g}\n",
      markdown_text(ref.method), ref.tolerance);
  if (ref.self_check)
    out += fmt::format(
        "- self-check: solved again 100 times tighter by another method ({}); the largest "
        "differences from the reference were {:.3g} m in position, {:.3g} m/s in velocity, "
        "{:.3g} rad in orientation and {:.3g} rad/s in spin\n",
        markdown_text(ref.self_check_method), ref.self_check->position, ref.self_check->velocity,
        ref.self_check->orientation, ref.self_check->spin);
  else
    out += "- self-check: none (" + markdown_text(ref.self_check_note) + ")\n";
  out += fmt::format(
      "- cost: time spent in step() only, in a pass after the accuracy runs (one timing per "
      "core); each run "
      "is repeated until the timed total reaches a minimum and the median is reported (the "
      "Every dt table and the JSON give the fastest and slowest repeat beside it); a median more "
      "than {:g} times "
      "the fastest repeat, over three repeats or more, says the machine was busy while that "
      "run was timed, and its cost is marked ~\n",
      kBusyMedianOverMin);
  out += "- versions:";
  for (const auto& [library, version] : results.versions)
    out += " " + markdown_text(library + " " + version) + ";";
  out += "\n";
  return out;
}

/// Every engine's settings, folded away.
std::string engine_settings_section(const CaseResults& results) {
  std::string out;
  // Every setting that changes an engine's results, folded away: long, and read when a
  // number needs explaining, not on a first look.
  std::set<std::string> seen;
  std::string settings;
  for (const RunRecord& run : results.runs)
    if (!run.engine_settings.empty() && seen.insert(run.backend).second)
      settings +=
          "- " + markdown_text(run.backend + ": " + settings_text(run.engine_settings)) + "\n";
  if (!settings.empty())
    out += fmt::format(
        "\n## Engine settings\n\n<details><summary>The settings each engine ran with ({} "
        "backends; also in the case's JSON)</summary>\n\n{}\n</details>\n",
        seen.size(), settings);
  return out;
}

}  // namespace

std::string results_markdown(const CaseResults& results, const PlotFiles& plots) {
  return header(results) + results_section(results) + motion_sections(results, plots) +
         stop_and_rotation_sections(results, plots) + claims_section(results, plots) +
         work_precision_section(results, plots) + stability_section(results) +
         every_dt_section(results) + reference_section(results) + engine_settings_section(results);
}

}  // namespace bb
