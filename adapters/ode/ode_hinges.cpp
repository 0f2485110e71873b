#include "ode_hinges.hpp"

#include <string>

namespace bb {

void make_ode_hinges(const World& scene, dWorldID world, const std::vector<dBodyID>& bodies) {
  for (const Hinge& h : scene.hinges) {
    if (scene.bodies[static_cast<std::size_t>(h.body)].fixed) continue;
    dJointID joint = dJointCreateHinge(world, nullptr);
    dJointAttach(joint, bodies[static_cast<std::size_t>(h.body)], nullptr);
    dJointSetHingeAnchor(joint, h.anchor.x(), h.anchor.y(), h.anchor.z());
    dJointSetHingeAxis(joint, h.axis.x(), h.axis.y(), h.axis.z());
    // ODE's defaults, set: no stops, no motor (zero force), the joint rows on the world's
    // ERP and CFM.
    dJointSetHingeParam(joint, dParamLoStop, -dInfinity);
    dJointSetHingeParam(joint, dParamHiStop, dInfinity);
    dJointSetHingeParam(joint, dParamFMax, 0);
    dJointSetHingeParam(joint, dParamVel, 0);
  }
}

void add_ode_hinge_settings(dWorldID world, Settings& out) {
  out.push_back(
      {"hinge",
       std::string("dJointCreateHinge per hinge, attached to (body, 0): the static environment; "
                   "dJointSetHingeAnchor at the anchor, dJointSetHingeAxis along the axis; "
                   "limit off (dParamLoStop -dInfinity, dParamHiStop dInfinity), motor off "
                   "(dParamFMax 0); its five rows use the world's ERP and CFM (hinge_erp, "
                   "hinge_cfm: dWorldSetERP/CFM), dParamStopERP/StopCFM/CFM acting only on "
                   "stops and motor; the CFM makes the joint slightly soft")});
  out.push_back({"hinge_erp", double(dWorldGetERP(world))});
  out.push_back({"hinge_cfm", double(dWorldGetCFM(world))});
}

}  // namespace bb
