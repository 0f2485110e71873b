#include "mujoco_model.hpp"

#include <fmt/format.h>

#include "../point_body.hpp"

namespace bb {

std::string mujoco_model_xml(const World& world, double dt) {
  // MuJoCo's own fluid forces off: drag, Magnus and wind come from the force model.
  std::string xml = fmt::format(
      "<mujoco model=\"beachball\">\n"
      "  <option timestep=\"{:.17g}\" gravity=\"{:.17g} {:.17g} {:.17g}\" integrator=\"Euler\" "
      "density=\"0\" viscosity=\"0\"/>\n"
      "  <worldbody>\n",
      dt, world.gravity.x(), world.gravity.y(), world.gravity.z());
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const Body& b = world.bodies[i];
    // A fixed body is part of the world; a moving one starts at the origin, its joints'
    // positions set from the scene once the data is made (mujoco_backend.cpp).
    if (b.fixed) {
      xml += fmt::format("    <body name=\"b{}\" pos=\"{:.17g} {:.17g} {:.17g}\"/>\n", i,
                         b.position.x(), b.position.y(), b.position.z());
      continue;
    }
    const Vec3 inertia = engine_inertia(b);
    xml += fmt::format("    <body name=\"b{}\">\n", i);
    if (world.dims == 3)
      xml += "      <freejoint/>\n";
    else
      xml +=
          "      <joint type=\"slide\" axis=\"1 0 0\"/>\n"
          "      <joint type=\"slide\" axis=\"0 1 0\"/>\n"
          "      <joint type=\"hinge\" axis=\"0 0 1\"/>\n";
    xml += fmt::format(
        "      <inertial pos=\"0 0 0\" mass=\"{:.17g}\" diaginertia=\"{:.17g} {:.17g} {:.17g}\"/>\n"
        "    </body>\n",
        b.mass, inertia.x(), inertia.y(), inertia.z());
  }
  return xml + "  </worldbody>\n</mujoco>\n";
}

}  // namespace bb
