// How far apart a contact pair of the scene (model/contact_pairs.hpp) stands, from the
// bodies' positions: the geometry the course methods and the reference share.
#pragma once

#include "contact/contact_geometry.hpp"
#include "model/contact_pairs.hpp"

namespace bb::contact {

/// Where the pair stands: `xa` is a's centre, `xb` and `qb` b's centre and orientation;
/// against the ground, where there is no b, `qb` is a's orientation. Spheres, points
/// (radius 0) and boxes against the plane; spheres against spheres and boxes (a is a box
/// only against the ground).
Proximity measure(const World& scene, const ContactPair& pair, const Eigen::Vector3d& xa,
                  const Eigen::Vector3d& xb, const Eigen::Quaterniond& qb);

}  // namespace bb::contact
