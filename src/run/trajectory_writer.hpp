// One run's state at every step as a CSV file (docs/output-files.md#trajectories), written
// from the stepping loop: a row per body per step, numbers that read back as the same
// double, and no allocation per step (rows go into a buffer reserved once, handed to the
// file system in whole rows).
#pragma once

#include <string>
#include <vector>

#include "model/state.hpp"
#include "model/world.hpp"

namespace bb {

/// Whether the trajectory files of `world` have the rotation columns: it has a body that can
/// turn (a sphere or a box that is not fixed; a point has no orientation).
bool trajectory_has_rotation(const World& world);

/// The header line of `world`'s trajectory files, with its newline.
std::string trajectory_header(const World& world);

class TrajectoryWriter {
 public:
  /// Rows of `world`'s bodies for the file `path`, which is made (or emptied) only when the
  /// first rows are handed over: a run that never had a state writes no file.
  TrajectoryWriter(std::string path, const World& world);
  ~TrajectoryWriter();
  TrajectoryWriter(const TrajectoryWriter&) = delete;
  TrajectoryWriter& operator=(const TrajectoryWriter&) = delete;

  /// The rows of every body at time `t` (a step count times dt).
  void write(double t, const State& state);
  /// Hands every row so far to the file system: a crash from here on keeps them.
  void flush();
  /// Flushes, syncs and closes the file: "" when every row reached it, else the OS's reason
  /// (a full disk, a file past `ulimit -f`).
  std::string close();
  const std::string& path() const { return path_; }

 private:
  void append(double x);

  std::string path_;
  std::vector<std::string> names_;  ///< per body: ",<name>"
  bool rotation_ = false;
  std::string buffer_;           ///< whole rows not yet written; its capacity never grows
  std::size_t state_bytes_ = 0;  ///< the most one state's rows can take
  bool rows_ = false;            ///< a row was written
  int fd_ = -1;
  std::string problem_;
};

}  // namespace bb
