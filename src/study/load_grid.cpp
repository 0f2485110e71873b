// [grid]: the spring-lattice generator of seed section 7 ("Sproing"), expanded into
// point bodies p<i>_<j>[_<k>] and springs between lattice neighbours.
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>

#include "model/text.hpp"
#include "study/load_case.hpp"
#include "study/load_parts.hpp"
#include "study/vector_limits.hpp"

namespace bb::load {

namespace {

/// splitmix64: a small deterministic generator, the same on every platform.
struct SplitMix64 {
  std::uint64_t state;
  double uniform_pm1() {  // in [-1, 1)
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
  }
};

/// Lattice offsets to connect, each pair once: axis, then face, then body diagonals.
std::vector<std::array<int, 3>> neighbour_offsets(int dims, int neighbours) {
  if (dims == 2) {
    std::vector<std::array<int, 3>> v = {{1, 0, 0}, {0, 1, 0}};
    if (neighbours >= 6) v.push_back({1, 1, 0});
    if (neighbours == 8) v.push_back({1, -1, 0});
    return v;
  }
  std::vector<std::array<int, 3>> v;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        // Keep one of each +/- pair: the first non-zero component is positive.
        const int first = dx != 0 ? dx : (dy != 0 ? dy : dz);
        const int order = std::abs(dx) + std::abs(dy) + std::abs(dz);
        if (first <= 0) continue;
        if (order == 1 || (order == 2 && neighbours >= 18) || (order == 3 && neighbours == 26))
          v.push_back({dx, dy, dz});
      }
  return v;
}

std::string particle_name(int dims, int i, int j, int k) {
  std::string n = "p";
  n += std::to_string(i);
  n += '_';
  n += std::to_string(j);
  if (dims == 3) {
    n += '_';
    n += std::to_string(k);
  }
  return n;
}

std::atomic<long> particles_made{0};

}  // namespace

}  // namespace bb::load

namespace bb {

GridCounts grid_counts(int dims, const std::vector<int>& size, int neighbours, bool anchored) {
  const double nx = size[0], ny = size[1], nz = dims == 3 ? size[2] : 1;
  GridCounts c;
  c.particles = nx * ny * nz;
  c.fixed = anchored ? nx * nz : 0.0;
  for (const auto& d : load::neighbour_offsets(dims, neighbours)) {
    const auto span = [](double n, int step) { return std::max(0.0, n - std::abs(step)); };
    c.springs += span(nx, d[0]) * span(ny, d[1]) * span(nz, d[2]);
    // Springs along the anchored row join two fixed particles and are left out.
    if (anchored && d[1] == 0) c.springs -= span(nx, d[0]) * span(nz, d[2]);
  }
  return c;
}

long grid_particles_made() {
  return load::particles_made.load();
}

}  // namespace bb

namespace bb::load {

std::optional<GridPlan> read_grid(TomlReader& root, const Scene& scene) {
  const toml::table* t = root.table("grid");
  if (t == nullptr) return std::nullopt;
  TomlReader r = sub_reader(root, *t, "[grid]");
  GridPlan plan;
  Grid& g = plan.grid;
  g.line = r.line();
  const std::vector<double> size = r.numbers("size", static_cast<std::size_t>(scene.dims));
  long particles = 1;
  for (double s : size) {
    if (s < 1.0 || s != std::floor(s) || s > 1e6)
      r.fail(r.line_of("size"), "'size' in [grid] must be whole numbers of at least 1");
    g.size.push_back(static_cast<int>(s));
    particles *= static_cast<long>(s);
    if (particles > kMaxGridParticles)
      r.fail(r.line_of("size"), "[grid] would make more than " + std::to_string(kMaxGridParticles) +
                                    " particles; that is beyond what beachball runs");
  }
  g.spacing = r.number_or("spacing", g.spacing);
  require_range(r, "spacing", g.spacing, kLeastSize, kMostSize);
  g.mass = r.number_or("mass", g.mass);
  require_range(r, "mass", g.mass, kLeastMass, kMostMass);
  g.neighbours = r.integer_or("neighbours", scene.dims == 2 ? 8 : 26);
  const bool ok = scene.dims == 2 ? (g.neighbours == 4 || g.neighbours == 6 || g.neighbours == 8)
                                  : (g.neighbours == 6 || g.neighbours == 18 || g.neighbours == 26);
  if (!ok)
    r.fail(r.line_of("neighbours"), scene.dims == 2
                                        ? "'neighbours' in a 2D [grid] must be 4, 6 or 8"
                                        : "'neighbours' in a 3D [grid] must be 6, 18 or 26");
  g.stiffness = r.number_or("stiffness", g.stiffness);
  require_range(r, "stiffness", g.stiffness, 0.0, kMostSpringConstant, false);
  g.damping = r.number_or("damping", g.damping);
  require_range(r, "damping", g.damping, 0.0, kMostSpringConstant);
  g.origin = r.vec3_or("origin", {});
  require_planar(r, scene, "origin", g.origin);
  plan.origin_line = r.line_of("origin");
  g.anchored = r.string_or("anchored", "none");
  if (g.anchored != "none" && g.anchored != "top-row")
    r.fail(r.line_of("anchored"), "'anchored' must be none or top-row, not '" + g.anchored + "'");
  g.rows = r.string_or("rows", "down");
  if (g.rows != "down" && g.rows != "up")
    r.fail(r.line_of("rows"), "'rows' must be down or up, not '" + g.rows + "'");
  g.jitter = r.number_or("jitter", 0.0);
  require_range(r, "jitter", g.jitter, 0.0, 0.0);
  // The corner farthest from the origin bounds every particle's position.
  const double row_sign = g.rows == "up" ? 1.0 : -1.0;
  const Vec3 reach{(g.size[0] - 1) * g.spacing + g.jitter,
                   row_sign * ((g.size[1] - 1) * g.spacing + g.jitter),
                   scene.dims == 3 ? (g.size[2] - 1) * g.spacing + g.jitter : 0.0};
  require_vector_range(r, "origin", g.origin, VectorKind::Position);
  for (const double sx : {0.0, 1.0})
    for (const double sy : {0.0, 1.0})
      for (const double sz : {0.0, 1.0}) {
        const Vec3 corner = g.origin + Vec3{sx * reach.x(), sy * reach.y(), sz * reach.z()};
        if (!vector_limit_problem(VectorKind::Position, corner).empty())
          r.fail(r.line_of("spacing"), "[grid] reaches " + short_number(corner.stableNorm()) +
                                           " m from the origin; a position is at most " +
                                           short_number(vector_limit(VectorKind::Position).most) +
                                           " m");
      }
  g.seed = static_cast<std::uint64_t>(r.integer_or("seed", 1));
  r.finish();
  plan.counts = grid_counts(scene.dims, g.size, g.neighbours, g.anchored == "top-row");
  return plan;
}

void expand_grid(Scene& scene, const GridPlan& plan) {
  Grid g = plan.grid;
  scene.bodies.reserve(scene.bodies.size() + static_cast<std::size_t>(plan.counts.particles));
  scene.springs.reserve(scene.springs.size() + static_cast<std::size_t>(plan.counts.springs));
  // Particles: column i along +x, row j downwards from the origin (upwards with rows = "up":
  // the seed's cloth starts raised above its anchored row), layer k along +z.
  const double row_step = g.rows == "up" ? g.spacing : -g.spacing;
  const int nx = g.size[0], ny = g.size[1], nz = scene.dims == 3 ? g.size[2] : 1;
  const auto index = [&](int i, int j, int k) {
    return static_cast<int>(scene.bodies.size()) - nx * ny * nz + (k * ny + j) * nx + i;
  };
  g.first_body = static_cast<int>(scene.bodies.size());
  SplitMix64 rng{g.seed};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        Body b;
        b.name = particle_name(scene.dims, i, j, k);
        b.shape = Shape::Point;
        b.mass = g.mass;
        b.line = g.line;
        b.fixed = g.anchored == "top-row" && j == 0;
        b.position = g.origin + Vec3{i * g.spacing, j * row_step, k * g.spacing};
        if (!b.fixed && g.jitter > 0.0) {
          const double jx = rng.uniform_pm1(), jy = rng.uniform_pm1(), jz = rng.uniform_pm1();
          b.position += Vec3{jx, jy, scene.dims == 3 ? jz : 0.0} * g.jitter;
        }
        scene.bodies.push_back(b);
        ++particles_made;
      }
  // Springs between lattice neighbours, at their undisturbed lattice distance.
  for (const auto& d : neighbour_offsets(scene.dims, g.neighbours))
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          const int i2 = i + d[0], j2 = j + d[1], k2 = k + d[2];
          if (i2 < 0 || i2 >= nx || j2 < 0 || j2 >= ny || k2 < 0 || k2 >= nz) continue;
          const int a = index(i, j, k), b = index(i2, j2, k2);
          if (scene.bodies[a].fixed && scene.bodies[b].fixed) continue;
          const double rest =
              g.spacing * std::sqrt(double(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
          scene.springs.push_back({a, b, g.stiffness, g.damping, rest, g.line});
        }
  scene.grid = g;
}

}  // namespace bb::load
