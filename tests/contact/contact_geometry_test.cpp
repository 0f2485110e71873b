// Contact geometry: distances, normals and points, as properties that hold for any pose.
#include "contact/contact_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace bb::contact {
namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

/// Deterministic random poses for property checks.
struct Poses {
  std::mt19937_64 rng{7};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng); }
  Vector3d point() { return {uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)}; }
  Quaterniond rotation() { return Quaterniond(Eigen::Vector4d::Random()).normalized(); }
};

TEST(ContactGeometry, SpherePlaneGapIsHeightAboveThePlaneLessTheRadius) {
  Poses poses;
  for (int i = 0; i < 100; ++i) {
    const Vector3d normal = poses.rotation() * Vector3d::UnitY();
    const Vector3d on_plane = poses.point();
    const double height = poses.uniform(-2, 2), radius = poses.uniform(0.1, 1);
    // A centre `height` above the plane, moved sideways along the plane.
    const Vector3d sideways = normal.unitOrthogonal() * poses.uniform(-3, 3);
    const Proximity p =
        sphere_plane(on_plane + sideways + height * normal, radius, on_plane, normal);
    EXPECT_NEAR(p.gap, height - radius, 1e-12);
    EXPECT_NEAR((p.point - on_plane).dot(normal), 0.0, 1e-12);
    EXPECT_TRUE(p.normal.isApprox(normal));
  }
}

TEST(ContactGeometry, SphereSphereIsSymmetricAndItsPointLiesOnTheSecondSphere) {
  Poses poses;
  for (int i = 0; i < 100; ++i) {
    const Vector3d a = poses.point(), b = poses.point();
    const double ra = poses.uniform(0.1, 2), rb = poses.uniform(0.1, 2);
    const Proximity ab = sphere_sphere(a, ra, b, rb), ba = sphere_sphere(b, rb, a, ra);
    EXPECT_NEAR(ab.gap, (a - b).norm() - ra - rb, 1e-12);
    EXPECT_NEAR(ab.gap, ba.gap, 1e-12);
    EXPECT_TRUE(ab.normal.isApprox(-ba.normal));
    EXPECT_NEAR((ab.point - b).norm(), rb, 1e-12);
    EXPECT_NEAR(ab.normal.norm(), 1.0, 1e-12);
  }
  EXPECT_NEAR(sphere_sphere(Vector3d::Zero(), 1, Vector3d::Zero(), 1).gap, -2.0, 0.0);
}

TEST(ContactGeometry, SphereBoxNearAFaceAnEdgeAndInside) {
  const Vector3d half(1.0, 0.5, 2.0);
  // Above the top face: plain height difference.
  Proximity top =
      sphere_box({0.3, 2.0, -1.0}, 0.5, Vector3d::Zero(), Quaterniond::Identity(), half);
  EXPECT_NEAR(top.gap, 2.0 - 0.5 - 0.5, 1e-12);
  EXPECT_TRUE(top.normal.isApprox(Vector3d::UnitY()));
  EXPECT_TRUE(top.point.isApprox(Vector3d(0.3, 0.5, -1.0)));
  // Beyond an edge: the distance is to the edge, along the diagonal.
  Proximity edge =
      sphere_box({2.0, 1.5, 0.0}, 0.25, Vector3d::Zero(), Quaterniond::Identity(), half);
  EXPECT_NEAR(edge.gap, std::sqrt(2.0) - 0.25, 1e-12);
  EXPECT_TRUE(edge.normal.isApprox(Vector3d(1, 1, 0).normalized()));
  // Inside, nearest the +x face (depth 0.1): pushed out through +x.
  Proximity inside =
      sphere_box({0.9, 0.0, 0.0}, 0.2, Vector3d::Zero(), Quaterniond::Identity(), half);
  EXPECT_NEAR(inside.gap, -0.1 - 0.2, 1e-12);
  EXPECT_TRUE(inside.normal.isApprox(Vector3d::UnitX()));
}

TEST(ContactGeometry, SphereBoxDoesNotDependOnHowTheWorldIsPlacedOrTurned) {
  Poses poses;
  const Vector3d half(1.0, 0.2, 0.7);
  for (int i = 0; i < 100; ++i) {
    const Vector3d centre = poses.point() * 0.5;
    const double radius = poses.uniform(0.05, 0.5);
    const Proximity local =
        sphere_box(centre, radius, Vector3d::Zero(), Quaterniond::Identity(), half);
    // The same configuration moved and turned as a whole.
    const Quaterniond turn = poses.rotation();
    const Vector3d shift = poses.point();
    const Proximity world = sphere_box(turn * centre + shift, radius, shift, turn, half);
    EXPECT_NEAR(world.gap, local.gap, 1e-12);
    EXPECT_TRUE(world.normal.isApprox(turn * local.normal, 1e-12));
    EXPECT_TRUE(world.point.isApprox(turn * local.point + shift, 1e-12));
  }
}

// A box flat on a face sits at its half height; turned 45 degrees about z it stands on an
// edge, lower by the half diagonal; on a slope the gap is measured along the slope's normal.
TEST(ContactGeometry, BoxPlaneLowestCornerOnLevelTurnedAndSloped) {
  const Vector3d half(1.0, 0.5, 0.25);
  const Vector3d up = Vector3d::UnitY();
  const Proximity flat =
      box_plane({3.0, 0.75, 1.0}, Quaterniond::Identity(), half, Vector3d::Zero(), up);
  EXPECT_NEAR(flat.gap, 0.25, 1e-15);
  EXPECT_NEAR(flat.point.y(), 0.0, 1e-15);
  const Quaterniond edge(Eigen::AngleAxisd(std::numbers::pi / 4.0, Vector3d::UnitZ()));
  const Proximity on_edge = box_plane({0.0, 2.0, 0.0}, edge, half, Vector3d::Zero(), up);
  // The lowest corner in the x-y plane is at 1.5 / sqrt(2) below the centre.
  EXPECT_NEAR(on_edge.gap, 2.0 - 1.5 / std::sqrt(2.0), 1e-14);
  // The same box on a 30 degree slope, turned with it: its face is flat on the slope.
  const double a = std::numbers::pi / 6.0;
  const Vector3d normal(-std::sin(a), std::cos(a), 0.0);
  const Quaterniond tilt(Eigen::AngleAxisd(a, Vector3d::UnitZ()));
  const Proximity on_slope = box_plane(Vector3d(5.0, 0.0, 0.0) + 0.5 * normal, tilt, half,
                                       Vector3d(5.0, 0.0, 0.0), normal);
  EXPECT_NEAR(on_slope.gap, 0.0, 1e-15);
  EXPECT_NEAR((on_slope.normal - normal).norm(), 0.0, 0.0);
}

}  // namespace
}  // namespace bb::contact
