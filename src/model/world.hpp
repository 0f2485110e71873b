// The model: what is simulated, in SI units. The World (bodies, ground, air, water, contacts,
// springs, the grid, hinges, impulses, waves) is what an engine needs to build a scene; it
// never sees how the world is examined (study/study.hpp).
#pragma once

#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/features.hpp"
#include "model/vec3.hpp"

namespace bb {

enum class Shape { Sphere, Box, Point };

/// A boat's sail (seed section 9, "Boat 1"), one of the parts a Body may have: planar and
/// friction-free, so the apparent wind pushes it only along its normal, by the drag formula
/// on its area.
struct Sail {
  double area = 0.0;         ///< square metres
  double coefficient = 1.0;  ///< C_s, dimensionless
  double angle = 0.0;        ///< degrees from the heading; the boom swings out to leeward
  /// N per radian of heel, > 0 when given; 0: not given, the boat stays upright.
  double heel_stiffness = 0.0;
};

/// How the wind pushes a flat plate along its normal n (seed section 8, "Wind").
enum class PlateLaw {
  /// The text's model: F = k a ((w - v) . n) n, linear in the relative wind, k constant.
  Course,
  /// The quadratic plate law of the sail: F = 1/2 rho C a ((w - v) . n) |(w - v) . n| n.
  Quadratic,
};

/// A flat panel in the wind: the box's broad face (normal along its smallest half extent)
/// pushed along its normal by the wind relative to it, at its centre.
struct Plate {
  PlateLaw law = PlateLaw::Course;
  double k = 0.0;            ///< the text's shape constant, N s / m^3 (law = course)
  double coefficient = 1.0;  ///< C, dimensionless (law = quadratic)
  double area = 0.0;         ///< square metres: the broad face's unless given
};

/// A boat's hull in still water: quadratic drag split along the heading and across it (the
/// keel), each direction with its own drag area C A.
struct Hull {
  double forward = 0.0;   ///< square metres, moving ahead
  double backward = 0.0;  ///< square metres, moving astern
  double sideways = 0.0;  ///< square metres, across the heading
  bool no_drift = false;  ///< sideways drag infinite: the boat goes only where it heads
};
/// One rigid body (or particle) of the scene, with the parts a boat or a panel may have.
struct Body {
  std::string name;
  Shape shape = Shape::Sphere;
  double radius = 0.0;                  ///< metres (sphere)
  Vec3 half_extents;                    ///< metres (box)
  double mass = 0.0;                    ///< kilograms; 0 for a fixed body
  bool shell = false;                   ///< sphere inertia 2/3 m r^2 when true, 2/5 m r^2 otherwise
  Vec3 position;                        ///< metres
  Vec3 velocity;                        ///< metres per second
  Quat orientation = Quat::Identity();  ///< unit quaternion; 2D scenes rotate about z only
  Vec3 angular_velocity;                ///< radians per second, world frame
  double drag_coefficient = 0.0;        ///< Cd, dimensionless
  double magnus = 0.0;                  ///< k in F = k (omega x (v - wind)), kilograms
  /// Newtons: the wind's push on a box's broad face when the face meets it square on; the
  /// box feels its part along the face's normal, (F.n) n, at its centre (seed section 8,
  /// the falling wall: F_w cos(phi) as the wall tips).
  Vec3 wind_force;
  Vec3 force;                  ///< newtons, world frame: a constant push at the centre
  Vec3 torque;                 ///< newton metres, world frame: a constant turn about the centre
  bool fixed = false;          ///< infinite mass, never moves
  std::optional<Sail> sail;    ///< a boat's sail, seen from above (2D, no gravity)
  std::optional<Hull> hull;    ///< a boat's hull in the [water]
  std::optional<Plate> plate;  ///< a panel the wind pushes along its normal
  int line = 0;                ///< line of the [[body]] header in the case file
};

/// Still air with an optional uniform wind.
struct Air {
  double density = 1.2;  ///< kilograms per cubic metre
  Vec3 wind;             ///< metres per second
};

/// Still water under the boats, seen from above.
struct Water {
  double density = 1000.0;  ///< kilograms per cubic metre
};

/// An infinite plane that every body touches.
struct Ground {
  Vec3 point;
  Vec3 normal{0.0, 1.0, 0.0};  ///< unit length after loading
  double restitution = 0.0;
  double friction_static = 0.0;
  double friction_kinetic = 0.0;
};

/// Which bodies touch each other, and how. `all_pairs` stands for ["*"]; `ground` for
/// ["<body>", "ground"], which gives one body's contact with the ground its own restitution
/// and friction (a block of each material on one floor).
struct Contact {
  bool all_pairs = false;
  bool ground = false;  ///< body_a against the ground; body_b unused
  int body_a = -1;
  int body_b = -1;
  double restitution = 0.0;
  double friction_static = 0.0;
  double friction_kinetic = 0.0;
  int line = 0;
};

/// A damped linear spring between two bodies' centres.
struct Spring {
  int body_a = -1;
  int body_b = -1;
  double stiffness = 0.0;    ///< newtons per metre
  double damping = 0.0;      ///< newton seconds per metre, along the spring axis
  double rest_length = 0.0;  ///< metres
  int line = 0;
};

/// The spring-lattice generator ("Sproing"); its particles and springs are already
/// expanded into Scene::bodies and Scene::springs.
struct Grid {
  std::vector<int> size;  ///< [cols, rows] in 2D, [x, y, z] in 3D
  double spacing = 1.0;
  double mass = 0.1;
  int neighbours = 8;
  double stiffness = 50.0;
  double damping = 0.2;
  Vec3 origin;
  std::string anchored = "none";  ///< "top-row": row j = 0, the row at the origin, is fixed
  std::string rows = "down";      ///< rows laid from the origin "down" (-y) or "up" (+y)
  double jitter = 0.0;
  std::uint64_t seed = 1;
  int first_body = 0;  ///< index of p0_0 in Scene::bodies; particle (i, j, k) follows at
                       ///< first_body + (k * rows + j) * cols + i
  int line = 0;
};

/// The simplified Gerstner surface of seed section 10 ("Gerstner waves"), as a profile in the
/// x-y plane: `points` surface points at rest positions x0 evenly from `from` to `to` at
/// height `level`, each offset by a point on a circle of radius `amplitude`,
///   x = x0 + amplitude cos(speed t + wavenumber x0),  y = level + amplitude sin(same phase).
/// Pure kinematics: nothing is integrated. The points are expanded into Scene::bodies
/// (point bodies w<i>, from `first_body` on), which only the formula moves.
struct Waves {
  double amplitude = 0.0;   ///< m
  double wavenumber = 1.0;  ///< 1/m
  double speed = 1.0;       ///< rad/s: the phase's rate
  int points = 0;
  double from = 0.0, to = 0.0;  ///< m, the rest positions' range along x
  double level = 0.0;           ///< m, the rest height
  int first_body = 0;
  int line = 0;

  /// The rest position x0 of surface point `i`.
  double rest_x(int i) const { return from + (to - from) * i / (points - 1); }
};

/// Surface point `i` of `waves` as a body: where the formula puts it at time 0, moving as
/// it moves there.
Body wave_point(const Waves& waves, int i);

/// Where surface point `i` of `waves` is at time `t` (s), and its velocity there: the
/// formula of seed section 10, the one place it is written.
std::pair<Vec3, Vec3> wave_motion(const Waves& waves, int i, double t);

/// A body turning about a fixed world axis.
struct Hinge {
  int body = -1;
  Vec3 anchor;
  Vec3 axis{0.0, 0.0, 1.0};  ///< unit length after loading
  int line = 0;
};

/// An instantaneous push at a given time ("Push", the plank hit): the body's velocity
/// changes by impulse / mass; off the centre it also gets an angular impulse r x J.
struct Impulse {
  int body = -1;
  double time = 0.0;          ///< seconds; a multiple of every dt
  Vec3 impulse;               ///< newton seconds
  std::optional<Vec3> point;  ///< world point where it acts, metres; none: the centre
  int line = 0;
};

/// What is simulated: the bodies and everything that acts on them. A backend sees only this
/// and its own settings (BackendSettings in backend.hpp), never how the case is examined.
struct World {
  int dims = 2;
  Vec3 gravity{0.0, -9.81, 0.0};
  std::optional<Air> air;
  std::optional<Water> water;
  std::optional<Ground> ground;
  std::vector<Body> bodies;
  std::vector<Contact> contacts;
  std::vector<Spring> springs;
  std::optional<Grid> grid;
  std::vector<Hinge> hinges;
  std::vector<Impulse> impulses;  ///< in time order
  std::optional<Waves> waves;

  /// The features this world uses; a backend must support all of them.
  FeatureSet features() const;
  /// Index of the body called `name`, or -1.
  int body_index(const std::string& name) const;
};

/// Principal moments of inertia (kg m^2) of a body about its centre.
Vec3 principal_inertia(const Body& body);

/// Frontal area (m^2) that drag acts on: pi r^2 for a sphere.
inline double frontal_area(const Body& body) {
  return body.shape == Shape::Sphere ? std::numbers::pi * body.radius * body.radius : 0.0;
}

}  // namespace bb
