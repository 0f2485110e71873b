#include "study/load_case.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>

#include "model/text.hpp"
#include "study/control_characters.hpp"
#include "study/load_parts.hpp"
#include "study/toml_depth.hpp"

namespace bb {

namespace {

using load::show;

void read_timing(TomlReader& root, Scene& scene) {
  scene.duration = root.number("duration");
  load::require_range(root, "duration", scene.duration, 0.0, 0.0, false);
  scene.sample = root.number("sample");
  load::require_range(root, "sample", scene.sample, 0.0, 0.0, false);
  if (!is_whole_multiple(scene.duration / scene.sample))
    root.fail(root.line_of("duration"), "'duration' (" + show(scene.duration) +
                                            " s) must be a whole number of samples of " +
                                            show(scene.sample) + " s");
  scene.dt = root.numbers("dt");
  for (double step : scene.dt) {
    if (step <= 0.0) root.fail(root.line_of("dt"), "every 'dt' must be greater than 0");
    if (step > scene.duration)
      root.fail(root.line_of("dt"), "'dt' " + show(step) + " s is longer than the duration");
    if (!is_whole_multiple(scene.sample / step))
      root.fail(root.line_of("dt"), "'dt' " + show(step) + " s does not divide 'sample' (" +
                                        show(scene.sample) + " s) into whole steps");
  }
  // The sweep runs from the largest step to the smallest.
  std::sort(scene.dt.begin(), scene.dt.end(), std::greater<>());
  if (std::adjacent_find(scene.dt.begin(), scene.dt.end()) != scene.dt.end())
    root.fail(root.line_of("dt"), "'dt' lists the same step twice");
  if (!root.has("report_dt") && scene.dt.size() > 1)
    root.fail(root.line(),
              "the case needs the key 'report_dt' (one of 'dt') when 'dt' has several steps");
  const double report = root.number_or("report_dt", scene.dt.front());
  const auto match = std::find_if(scene.dt.begin(), scene.dt.end(), [&](double step) {
    return std::abs(step - report) <= 1e-12 * step;
  });
  if (match == scene.dt.end())
    root.fail(root.line_of("report_dt"), "'report_dt' " + show(report) + " s is not one of 'dt'");
  scene.report_dt = *match;
}

void read_header(TomlReader& root, Scene& scene) {
  scene.name = root.string("name");
  if (character_count(scene.name) > kMaxNameLength)
    root.fail(root.line_of("name"), "'name' is " + std::to_string(character_count(scene.name)) +
                                        " characters long; a case name may be at most " +
                                        std::to_string(kMaxNameLength) +
                                        " (it names the output files)");
  if (!is_name(scene.name, false))
    root.fail(root.line_of("name"),
              "'name' must use only a-z, 0-9 and _ (it names the output files), not '" +
                  scene.name + "'");
  // The report's own pages sit beside the cases' (README.md on a file system that ignores
  // case, claims.md): a case may not take their names.
  for (const auto& [taken, page] :
       {std::pair<const char*, const char*>{"claims", "claims.md"}, {"readme", "README.md"}})
    if (scene.name == taken)
      root.fail(root.line_of("name"), "'name' '" + scene.name + "' is taken by the report's " +
                                          page + " (its page would overwrite it); rename the case");
  scene.title = root.string_or("title", scene.name);
  scene.seed = root.string_or("seed", "");
  scene.dims = root.integer("dims");
  if (scene.dims != 2 && scene.dims != 3)
    root.fail(root.line_of("dims"), "'dims' must be 2 or 3, not " + std::to_string(scene.dims));
  scene.gravity = root.vec3_or("gravity", scene.gravity);
  load::require_planar(root, scene, "gravity", scene.gravity);
  load::require_vector_range(root, "gravity", scene.gravity, VectorKind::Gravity);
}

/// The number of values one [[sweep]] table asks for and the line of its values, read ahead
/// of the sweep itself: 0 when they are malformed (read_sweep names the problem).
std::pair<double, int> sweep_count(const toml::table& t, int fallback_line) {
  if (const toml::array* values = t.get_as<toml::array>("values"))
    return {values->size() <= kMaxSweepValues ? static_cast<double>(values->size()) : 0.0,
            node_line(*values, fallback_line)};
  if (const toml::array* range = t.get_as<toml::array>("range"); range && range->size() == 3) {
    const std::optional<double> count = (*range)[2].value<double>();
    const bool valid =
        count && *count == std::floor(*count) && *count >= 2 && *count <= kMaxSweepValues;
    return {valid ? *count : 0.0, node_line(*range, fallback_line)};
  }
  return {0.0, 0};
}

/// The smallest value a [[sweep]] of "dt" asks for (a range's first), read ahead; 0 for
/// another parameter or none it can read (read_sweep names the problem).
double least_swept_step(const toml::table& t) {
  if (t["parameter"].value<std::string>() != "dt") return 0.0;
  const toml::array* list = t.get_as<toml::array>("values");
  if (!list) list = t.get_as<toml::array>("range");
  double least = 0.0;
  if (list)
    for (std::size_t i = 0; i < list->size() && (t.contains("values") || i == 0); ++i)
      if (const std::optional<double> v = (*list)[i].value<double>(); v && *v > 0.0)
        least = least > 0.0 ? std::min(least, *v) : *v;
  return least;
}

/// The points the [[sweep]]s ask for (a map's: both counts multiplied), the line of the
/// last one's values and the smallest swept step, read ahead: 0 points without one.
void read_sweep_size(TomlReader& root, CaseSize& size) {
  const std::vector<const toml::table*> sweeps = root.tables("sweep");
  for (std::size_t i = 0; i < sweeps.size() && i < 2; ++i) {
    const auto [count, line] = sweep_count(*sweeps[i], root.line());
    size.sweep_points = i == 0 ? count : size.sweep_points * count;
    size.sweep_line = line;
    if (const double step = least_swept_step(*sweeps[i]); step > 0.0) size.sweep_least_dt = step;
  }
}

/// What the case asks for, from the bodies read so far, the [grid]'s numbers and a look
/// ahead at [[spring]], [[contact]] and [[sweep]]: nothing of the grid is built yet.
CaseSize case_size(TomlReader& root, const Scene& scene,
                   const std::optional<load::GridPlan>& grid) {
  CaseSize size;
  size.duration = scene.duration;
  size.sample = scene.sample;
  size.dt = scene.dt;
  size.report_dt = scene.report_dt;
  size.case_line = root.line();
  size.sample_line = root.line_of("sample");
  size.dt_line = root.line_of("dt");
  size.bodies = static_cast<double>(scene.bodies.size());
  for (const Body& b : scene.bodies) size.fixed_bodies += b.fixed ? 1.0 : 0.0;
  if (grid) {
    size.bodies += grid->counts.particles;
    size.fixed_bodies += grid->counts.fixed;
    size.springs += grid->counts.springs;
  }
  size.springs += static_cast<double>(root.tables("spring").size());
  for (const toml::table* t : root.tables("contact")) {
    const toml::array* bodies = t->get_as<toml::array>("bodies");
    const bool every = bodies && bodies->size() == 1 && (*bodies)[0].value<std::string>() == "*";
    if (every && !size.all_pairs) size.contact_line = node_line(*t, root.line());
    size.all_pairs = size.all_pairs || every;
    size.named_pairs += every ? 0.0 : 1.0;
  }
  read_sweep_size(root, size);
  return size;
}

}  // namespace

Scene parse_case(std::string_view text, const std::string& file, const CaseVocabulary& vocabulary) {
  refuse_control_characters(text, file);
  // toml++ recurses on key parts and nesting: bound them before it sees the text.
  check_toml_depth(text, file);
  toml::table table;
  try {
    table = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw CaseError(file, static_cast<int>(e.source().begin.line),
                    "not valid TOML: " + std::string(e.description()));
  }
  Scene scene;
  scene.file = file;
  scene.source = std::string(text);
  TomlReader root(table, file, "the case", 1);
  // The order matters: bodies come before what refers to them, names before gates.
  read_header(root, scene);
  read_timing(root, scene);
  load::read_air_and_ground(root, scene);
  const std::vector<load::Resting> resting = load::read_bodies(root, scene);
  const std::optional<load::GridPlan> grid = load::read_grid(root, scene);
  load::read_waves(root, scene, grid.has_value());
  // Every limit that numbers decide, before the grid's particles and springs are made.
  check_case_size(file, case_size(root, scene, grid));
  if (grid) {
    load::expand_grid(scene, *grid);
    for (std::size_t i = static_cast<std::size_t>(scene.grid->first_body); i < scene.bodies.size();
         ++i)
      load::refuse_ground_overlap(root, scene, scene.bodies[i], grid->origin_line);
  }
  if (scene.bodies.empty())
    root.fail(root.line(), "the case has no [[body]], no [grid] and no [waves]");
  const load::BodyNames names(root, scene);
  load::read_contacts(root, scene, names);
  load::require_resting_contacts(root, scene, resting);
  load::read_springs(root, scene, names);
  load::read_hinges(root, scene, names);
  load::read_impulses(root, scene, names);
  load::read_course(root, scene);
  load::read_engines(root, scene, vocabulary.engines);
  load::read_observes(root, scene, names, vocabulary);
  load::read_gates(root, scene, vocabulary.engines);
  load::read_claims(root, scene, vocabulary.engines);
  load::read_sweep(root, scene);
  load::check_region_claims(scene);
  load::read_report_and_stability(root, scene);
  load::read_baseline(root, scene);
  root.finish();
  return scene;
}

Scene load_case(const std::string& path, const CaseVocabulary& vocabulary) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw CaseError(path, 0, "no such file");
  if (fs::is_directory(status))
    throw CaseError(path, 0, "is a directory; give a case file (.toml)");
  if (!fs::is_regular_file(status)) throw CaseError(path, 0, "is not a regular file");
  const auto size = fs::file_size(path, ec);
  if (ec) throw CaseError(path, 0, "cannot be read: " + ec.message());
  if (size > kMaxCaseFileBytes)
    throw CaseError(path, 0,
                    "is " + std::to_string(size / 1024) +
                        " KiB; a case file may be at most 1 MiB (a scene is a few kilobytes)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(path, 0, "cannot be opened for reading");
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().find_first_not_of(" \t\r\n") == std::string::npos)
    throw CaseError(
        path, 0, "is empty; a case needs at least name, dims, duration, sample, dt and a [[body]]");
  return parse_case(text.str(), path, vocabulary);
}

}  // namespace bb
