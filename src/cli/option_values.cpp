#include "cli/option_values.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "study/case_error.hpp"

namespace bb::cli {

namespace {

/// The whole of `text` as a finite number, or NaN.
double whole_number(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nan("");
  return value;
}

}  // namespace

void check_range(const std::string& option, double value, const OptionRange& range) {
  if (std::isfinite(value) && value >= range.min && value <= range.max) return;
  const std::string unit = *range.unit ? std::string(" ") + range.unit : "";
  throw CaseError(option, 0,
                  fmt::format("{:g}{} is outside the accepted range {:g} to {:g}{}", value, unit,
                              range.min, range.max, unit));
}

std::vector<std::string> split_list(const std::string& option, const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string part =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (part.empty())
      throw CaseError(option, 0,
                      "'" + text +
                          "' has an empty entry; give names or values separated by "
                          "single commas");
    out.push_back(part);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

double parse_step(const std::string& text) {
  const auto slash = text.find('/');
  const double value = slash == std::string::npos ? whole_number(text)
                                                  : whole_number(text.substr(0, slash)) /
                                                        whole_number(text.substr(slash + 1));
  if (std::isfinite(value) && value > 0.0) return value;
  throw CaseError("--dt", 0,
                  "'" + text + "' is not a positive, finite step in seconds (write 0.01 or 1/60)");
}

TrajectoryImport parse_trajectory_import(const std::string& text) {
  const std::size_t at = text.find('@');
  const std::size_t equals = at == std::string::npos ? at : text.find('=', at);
  const auto refuse = [&](const std::string& why) -> TrajectoryImport {
    throw CaseError("--trajectory", 0,
                    "'" + text + "' " + why + " (write NAME@DT=FILE, e.g. mine@1/60=mine-60.csv)");
  };
  if (equals == std::string::npos) return refuse("has no '@' and '='");
  TrajectoryImport out{text.substr(0, at), 0.0, text.substr(equals + 1)};
  if (out.name.empty() ||
      out.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz"
                                 "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.+") != std::string::npos)
    return refuse("has a NAME that is not letters, digits and - _ . +");
  if (out.file.empty()) return refuse("names no FILE");
  out.dt = parse_step(text.substr(at + 1, equals - at - 1));
  return out;
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto whole = [](const std::string& part) {
    return !part.empty() && part.size() <= 5 &&
           part.find_first_not_of("0123456789") == std::string::npos;
  };
  if (slash != std::string::npos && whole(text.substr(0, slash)) && whole(text.substr(slash + 1))) {
    const Shard shard{std::stoi(text.substr(0, slash)), std::stoi(text.substr(slash + 1))};
    if (shard.index >= 1 && shard.count <= 10000 && shard.index <= shard.count) return shard;
  }
  throw CaseError("--shard", 0,
                  "'" + text + "' is not a share I/N of the work (1 <= I <= N <= 10000, e.g. 2/4)");
}

}  // namespace bb::cli
