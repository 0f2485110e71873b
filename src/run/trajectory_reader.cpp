#include "run/trajectory_reader.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <string>

#include "files/whole_file.hpp"
#include "model/text.hpp"
#include "run/trajectory_writer.hpp"
#include "study/case_error.hpp"

namespace bb {

namespace {

constexpr const char* kPositionColumns = "t,body,x,y,z,vx,vy,vz";
constexpr const char* kRotationColumns = ",qw,qx,qy,qz,wx,wy,wz";
constexpr const char* kCostColumn = ",cost_ns";

/// The file's layout, from its header.
struct Columns {
  bool rotation = false;
  bool cost = false;
  std::size_t count() const { return 8 + (rotation ? 7 : 0) + (cost ? 1 : 0); }
};

/// `text` split at each comma.
std::vector<std::string> fields_of(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
    out.push_back(text.substr(start, comma - start));
  out.push_back(text.substr(start));
  return out;
}

/// The whole of `text` as a number ("nan" and "inf" too), or nullopt.
std::optional<double> number_of(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

/// Reads the file's rows one at a time, checking each against the case.
class RowReader {
 public:
  RowReader(const Scene& scene, double dt, const std::string& file)
      : scene_(scene), dt_(dt), file_(file), per_sample_(scene.steps_per_sample(dt)) {
    out_.file = file;
    out_.dt = dt;
    out_.run_steps = static_cast<long>(per_sample_) * scene.sample_count();
  }

  [[noreturn]] void fail(int line, const std::string& problem) const {
    throw CaseError(file_, line, problem);
  }

  void header(const std::string& text) {
    const std::string wanted = trajectory_header(scene_);
    const std::string position = kPositionColumns;
    std::string rest = text.substr(0, position.size()) == position ? text.substr(position.size())
                                                                   : std::string("?");
    if (rest.rfind(kRotationColumns, 0) == 0) {
      columns_.rotation = true;
      rest = rest.substr(std::string(kRotationColumns).size());
    }
    if (rest == kCostColumn) {
      columns_.cost = true;
      rest.clear();
    }
    if (!rest.empty())
      fail(1, "the header is '" + text + "'; a trajectory of this case starts with '" +
                  wanted.substr(0, wanted.size() - 1) + "' (and may end with ',cost_ns')");
    if (trajectory_has_rotation(scene_) && !columns_.rotation)
      fail(1,
           "the header has no columns qw,qx,qy,qz,wx,wy,wz, and this case has bodies that "
           "turn: '" +
               wanted.substr(0, wanted.size() - 1) + "'");
  }

  void row(int line, const std::string& text) {
    const std::vector<std::string> fields = fields_of(text);
    if (fields.size() != columns_.count())
      fail(line, "the row has " + std::to_string(fields.size()) + " columns, the header " +
                     std::to_string(columns_.count()));
    std::vector<double> values;
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i == 1) continue;
      const auto value = number_of(fields[i]);
      if (!value) fail(line, "'" + fields[i] + "' is not a number");
      values.push_back(*value);
    }
    const double t = values[0];
    if (!std::isfinite(t) || t < 0.0) fail(line, "t = " + fields[0] + " is not a time");
    const int body = scene_.body_index(fields[1]);
    if (body < 0) fail(line, "'" + fields[1] + "' is not a body of case " + scene_.name);
    if (t != time_ || rows_in_time_ == 0) next_time(line, t, fields[0]);
    if (seen_[body]) fail(line, "body '" + fields[1] + "' twice at t = " + fields[0]);
    seen_[body] = true;
    ++rows_in_time_;
    BodyState& b = out_.states.back()[body];
    b.position = Vec3(values[1], values[2], values[3]);
    b.velocity = Vec3(values[4], values[5], values[6]);
    if (columns_.rotation) {
      b.orientation = Quat(values[7], values[8], values[9], values[10]);
      b.angular_velocity = Vec3(values[11], values[12], values[13]);
    }
    for (std::size_t i = 1; i < values.size() - (columns_.cost ? 1 : 0); ++i)
      if (!std::isfinite(values[i]) && !first_non_finite_) first_non_finite_ = {line, step_};
    if (columns_.cost) cost(line, values.back(), fields.back());
  }

  /// The rows read so far: a last time without every body is not a row.
  ImportedTrajectory finish() {
    if (out_.states.empty()) fail(2, "the file has no rows");
    if (rows_in_time_ < scene_.bodies.size()) {
      out_.states.pop_back();
      if (columns_.cost && !out_.cost_ns.empty() && step_ > 0) out_.cost_ns.pop_back();
    }
    if (out_.states.empty()) fail(2, "the file has no time with a row for every body");
    return std::move(out_);
  }

 private:
  /// A row at a new time: the last time had every body, this one is on the grid, after it.
  void next_time(int line, double t, const std::string& text) {
    if (!out_.states.empty() && rows_in_time_ < scene_.bodies.size())
      for (std::size_t i = 0; i < seen_.size(); ++i)
        if (!seen_[i])
          fail(time_line_, "body '" + scene_.bodies[i].name + "' has no row at t = " +
                               short_number(time_) + " (every time has a row for every body)");
    if (!out_.states.empty() && t < time_)
      fail(line, "t = " + text + " comes after t = " + short_number(time_) +
                     ": the rows are out of order (times increase)");
    const long k = std::lround(t / dt_);
    if (std::abs(t - static_cast<double>(k) * dt_) > kStepTimeTolerance * dt_)
      fail(line, "t = " + text + " is not on the grid of steps of " + format_dt(dt_) +
                     " s (t = k dt to within " + short_number(kStepTimeTolerance) + " dt)");
    if (out_.states.empty() && k != 0) fail(line, "the first row is at t = " + text + ", not 0");
    if (out_.states.size() == 1) {
      if (k != 1 && k != per_sample_)
        fail(line, "after t = 0 the next time is t = " + text + " (" + std::to_string(k) +
                       " steps): rows are at every step, or at every sample (every " +
                       std::to_string(per_sample_) + " steps, " + short_number(scene_.sample) +
                       " s)");
      out_.stride = k;
    }
    const long expected = out_.states.empty() ? 0 : step_ + out_.stride;
    if (k != expected)
      fail(line, "t = " + text + " follows t = " + short_number(time_) + ": the time " +
                     short_number(static_cast<double>(expected) * dt_) + " s is missing (rows " +
                     (out_.stride == 1 ? std::string("at every step")
                                       : "at every sample, " + short_number(scene_.sample) + " s") +
                     ")");
    if (k > out_.run_steps)
      fail(line, "t = " + text + " is past the end of the case's run (" +
                     short_number(static_cast<double>(out_.run_steps) * dt_) + " s)");
    // Not a number or infinite only in a run's last rows: up to the sample where it diverged.
    if (first_non_finite_) {
      const long s = first_non_finite_->step;
      if (k > (s + per_sample_ - 1) / per_sample_ * per_sample_) not_finite_then_more(line);
    }
    step_ = k;
    time_ = t;
    time_line_ = line;
    rows_in_time_ = 0;
    seen_.assign(scene_.bodies.size(), false);
    out_.states.emplace_back(scene_.bodies.size());
  }

  [[noreturn]] void not_finite_then_more(int line) const {
    fail(first_non_finite_->line,
         "a value that is not finite, and rows after it to line " + std::to_string(line) +
             " past the next sample: nan or inf may stand only in a run's last rows, up to the "
             "sample where it diverged");
  }

  /// The program's time per step at this time (every row of a time gives it; the first counts).
  void cost(int line, double ns, const std::string& text) {
    if (!std::isfinite(ns) || ns < 0.0)
      fail(line, "cost_ns '" + text + "' is not a time in nanoseconds (finite, 0 or more)");
    if (rows_in_time_ == 1 && step_ > 0) out_.cost_ns.push_back(ns);
  }

  struct Place {
    int line;
    long step;
  };
  const Scene& scene_;
  const double dt_;
  const std::string file_;
  const long per_sample_;
  Columns columns_;
  ImportedTrajectory out_;
  long step_ = 0;
  double time_ = 0.0;
  int time_line_ = 0;
  std::size_t rows_in_time_ = 0;
  std::vector<bool> seen_;
  std::optional<Place> first_non_finite_;
};

}  // namespace

ImportedTrajectory read_trajectory(const Scene& scene, double dt, const std::string& file) {
  const std::optional<std::string> read = read_whole_file(file);
  if (!read)
    throw CaseError(
        file, 0,
        std::ifstream(file) ? "cannot be read" : "cannot be read (no such file, or not readable)");
  const std::string& text = *read;
  RowReader reader(scene, dt, file);
  int line = 0;
  std::size_t start = 0;
  // Only whole lines: a last line without its newline is not a row (a program stopped there).
  for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
    std::string row = text.substr(start, end - start);
    if (!row.empty() && row.back() == '\r') row.pop_back();
    if (++line == 1)
      reader.header(row);
    else
      reader.row(line, row);
  }
  if (line == 0) throw CaseError(file, 1, "the file has no header line");
  return reader.finish();
}

}  // namespace bb
