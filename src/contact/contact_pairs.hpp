// Which things in a scene can touch, and how far apart they are: the ground with every
// moving body, and the pairs the case's [[contact]] entries name. Shared by the course
// methods and the reference so both see the same contacts.
#pragma once

#include <vector>

#include "contact/contact_geometry.hpp"
#include "scene/scene.hpp"

namespace bb::contact {

/// Two things that may touch: body `a` against body `b`, or against the ground (b = -1).
struct ContactPair {
  int a = -1;
  int b = -1;  ///< -1: the ground; a fixed box, when one takes part, is always b
  double restitution = 0.0;
  bool ground() const { return b < 0; }
};

/// Every pair that can touch, the ground's first, in a fixed order. A pair named by several
/// [[contact]] entries takes the first; two fixed bodies never touch.
std::vector<ContactPair> contact_pairs(const Scene& scene);

/// Where the pair stands: `xa` is a's centre, `xb` and `qb` b's centre and orientation
/// (ignored for the ground). Spheres and points (radius 0) against the plane, spheres and
/// boxes; a is never a box.
Proximity measure(const Scene& scene, const ContactPair& pair, const Eigen::Vector3d& xa,
                  const Eigen::Vector3d& xb, const Eigen::Quaterniond& qb);

}  // namespace bb::contact
