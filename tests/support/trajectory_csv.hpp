// Reading back a trajectory file (docs/output-files.md#trajectories) in a test: its header
// and its rows, every number parsed to the double it was written from.
#pragma once

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "files/whole_file.hpp"

namespace bb::test {

struct TrajectoryRow {
  double t = 0.0;
  std::string body;
  std::vector<double> values;  ///< x, y, z, vx, vy, vz, then qw..wz where the file has them
};

struct TrajectoryCsv {
  std::string header;
  std::vector<TrajectoryRow> rows;
  bool complete = true;  ///< every line ended with a newline and had the header's columns
};

/// The file at `path`, split at commas, each number read with strtod.
inline TrajectoryCsv read_trajectory(const std::string& path) {
  const std::string text = read_whole_file(path).value_or("");
  TrajectoryCsv out;
  std::istringstream lines(text);
  std::getline(lines, out.header);
  std::size_t columns = 1;
  for (char c : out.header) columns += c == ',';
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cells;
    std::istringstream split(line);
    for (std::string cell; std::getline(split, cell, ',');) cells.push_back(cell);
    if (cells.size() != columns) {
      out.complete = false;
      continue;
    }
    TrajectoryRow row;
    row.t = std::strtod(cells[0].c_str(), nullptr);
    row.body = cells[1];
    for (std::size_t i = 2; i < cells.size(); ++i)
      row.values.push_back(std::strtod(cells[i].c_str(), nullptr));
    out.rows.push_back(std::move(row));
  }
  out.complete = out.complete && (text.empty() || text.back() == '\n');
  return out;
}

}  // namespace bb::test
