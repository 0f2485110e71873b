#include "run/trajectory_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>

#include "files/atomic_file.hpp"

namespace bb {

namespace {

/// Characters a number may take: the shortest form that reads back as the same double is
/// at most 24 ("-2.2250738585072014e-308"), and a comma.
constexpr std::size_t kNumberBytes = 32;
/// Numbers in a row with rotation: t and 14 components.
constexpr std::size_t kRowNumbers = 15;
/// The buffer handed to the file system at once, at least.
constexpr std::size_t kBufferBytes = 1 << 20;

}  // namespace

bool trajectory_has_rotation(const World& world) {
  return std::any_of(world.bodies.begin(), world.bodies.end(),
                     [](const Body& b) { return !b.fixed && b.shape != Shape::Point; });
}

std::string trajectory_header(const World& world) {
  return std::string("t,body,x,y,z,vx,vy,vz") +
         (trajectory_has_rotation(world) ? ",qw,qx,qy,qz,wx,wy,wz" : "") + "\n";
}

TrajectoryWriter::TrajectoryWriter(std::string path, const World& world)
    : path_(std::move(path)), rotation_(trajectory_has_rotation(world)) {
  const std::string header = trajectory_header(world);
  std::size_t longest_name = 0;
  for (const Body& b : world.bodies) {
    names_.push_back("," + b.name);
    longest_name = std::max(longest_name, b.name.size());
  }
  state_bytes_ = world.bodies.size() * (kRowNumbers * kNumberBytes + longest_name + 2);
  buffer_.reserve(std::max(kBufferBytes, header.size() + 2 * state_bytes_));
  buffer_.append(header);
}

TrajectoryWriter::~TrajectoryWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void TrajectoryWriter::append(double x) {
  char text[kNumberBytes];
  text[0] = ',';
  const auto end = std::to_chars(text + 1, text + sizeof text, x).ptr;
  buffer_.append(text, end);
}

void TrajectoryWriter::write(double t, const State& state) {
  // Room for this state's rows, so that the buffer never grows (no allocation per step).
  if (buffer_.size() + state_bytes_ > buffer_.capacity()) flush();
  rows_ = true;
  char stamp[kNumberBytes];
  const auto stamp_end = std::to_chars(stamp, stamp + sizeof stamp, t).ptr;
  for (std::size_t i = 0; i < state.size() && i < names_.size(); ++i) {
    const BodyState& b = state[i];
    buffer_.append(stamp, stamp_end);
    buffer_ += names_[i];
    for (int k = 0; k < 3; ++k) append(b.position[k]);
    for (int k = 0; k < 3; ++k) append(b.velocity[k]);
    if (rotation_) {
      append(b.orientation.w());
      append(b.orientation.x());
      append(b.orientation.y());
      append(b.orientation.z());
      for (int k = 0; k < 3; ++k) append(b.angular_velocity[k]);
    }
    buffer_ += '\n';
  }
}

void TrajectoryWriter::flush() {
  if (!rows_) return;
  // After a failure the rows go nowhere: close() says why.
  if (problem_.empty() && fd_ < 0) {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd_ < 0) problem_ = os_reason();
  }
  if (problem_.empty()) problem_ = write_all(fd_, buffer_);
  buffer_.clear();
}

std::string TrajectoryWriter::close() {
  flush();
  if (fd_ >= 0) {
    if (fsync(fd_) != 0 && problem_.empty()) problem_ = os_reason();
    if (::close(fd_) != 0 && problem_.empty()) problem_ = os_reason();
    fd_ = -1;
  }
  return problem_;
}

}  // namespace bb
