// The force a hinge exerts on its body (seed section 8: the falling wall's push "against the
// contact point with the ground", where a weak anchor would break), recovered from each
// sampled state by the hinge's law: the body turns about the axis under the forces at its
// centre, so the hinge supplies m a - F, a the centre's acceleration that turning implies.
#pragma once

#include <optional>

#include "observe/observable_measure.hpp"

namespace bb {

/// The hinge `body` turns on, or nullptr for a body on no hinge.
const Hinge* hinge_of(const World& scene, int body);

/// The force (N) hinge `hinge` exerts on its body in `state`: m a - F with F gravity plus
/// `force` (the force model's, at its centre), a = alpha x r + omega x (omega x r) from the
/// torque of F about the axis. Exact for a body turning free of anything else.
Vec3 hinge_force(const Scene& scene, const Hinge& hinge, const BodyState& state,
                 const Vec3& force = Vec3::Zero());

/// hinge_force (N), the hinge's force on the body when it has turned 45 degrees from its
/// start, interpolated linearly in the turn between the samples either side (a force read
/// at a fixed turn compares backends; its largest value, just before a wall lands, would
/// depend on where the samples fall); a note when the body is on no hinge or never turns
/// that far.
ObservableValue measure_hinge_force(const Scene& scene, const Observe& observe,
                                    const Trajectory& trajectory, const EventTrace*);

}  // namespace bb
