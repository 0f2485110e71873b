#include "ode_contacts.hpp"

#include <cstdint>

#include "../engine_friction.hpp"
#include "model/contact_pairs.hpp"

namespace bb {

namespace {

/// Geom data carries the index of what the geom belongs to (the ground: the last index).
void* index_data(int index) {
  return reinterpret_cast<void*>(static_cast<std::intptr_t>(index));
}
int index_of(dGeomID geom) {
  return static_cast<int>(reinterpret_cast<std::intptr_t>(dGeomGetData(geom)));
}

}  // namespace

bool scene_has_contacts(const World& scene) {
  return scene.ground.has_value() || !scene.contacts.empty();
}

OdeContacts::OdeContacts(const World& scene, dWorldID world, const std::vector<dBodyID>& bodies,
                         dReal bounce_vel)
    : world_(world),
      space_(dSimpleSpaceCreate(nullptr)),
      joints_(dJointGroupCreate(0)),
      bounce_vel_(bounce_vel),
      count_(static_cast<int>(scene.bodies.size()) + 1),
      surfaces_(static_cast<std::size_t>(count_ * count_)) {
  std::vector<bool> touches(scene.bodies.size(), false);
  for (const ContactPair& pair : contact_pairs(scene)) {
    const int b = pair.ground() ? count_ - 1 : pair.b;
    const OdeSurface s{true, static_cast<dReal>(pair.restitution),
                       static_cast<dReal>(engine_friction(pair))};
    surfaces_[static_cast<std::size_t>(pair.a * count_ + b)] = s;
    surfaces_[static_cast<std::size_t>(b * count_ + pair.a)] = s;
    touches[static_cast<std::size_t>(pair.a)] = true;
    if (!pair.ground()) touches[static_cast<std::size_t>(pair.b)] = true;
  }
  // A geom for each body that can touch something, moving with its body.
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const Body& body = scene.bodies[i];
    if (!touches[i] || body.shape == Shape::Point) continue;
    const Vec3 size = 2.0 * body.half_extents;
    dGeomID geom = body.shape == Shape::Sphere ? dCreateSphere(space_, body.radius)
                                               : dCreateBox(space_, size.x(), size.y(), size.z());
    dGeomSetBody(geom, bodies[i]);
    dGeomSetData(geom, index_data(static_cast<int>(i)));
  }
  // The ground: ODE's plane n . x = d, static (no body).
  if (scene.ground) {
    const Vec3 n = scene.ground->normal;
    dGeomID plane = dCreatePlane(space_, n.x(), n.y(), n.z(), n.dot(scene.ground->point));
    dGeomSetData(plane, index_data(count_ - 1));
  }
}

OdeContacts::~OdeContacts() {
  dJointGroupDestroy(joints_);
  dSpaceDestroy(space_);
}

const OdeSurface& OdeContacts::surface(int a, int b) const {
  return surfaces_[static_cast<std::size_t>(a * count_ + b)];
}

void OdeContacts::collide() {
  dSpaceCollide(space_, this, &OdeContacts::near_callback);
}

void OdeContacts::clear() {
  dJointGroupEmpty(joints_);
}

void OdeContacts::near_callback(void* data, dGeomID a, dGeomID b) {
  auto* self = static_cast<OdeContacts*>(data);
  const OdeSurface& s = self->surface(index_of(a), index_of(b));
  if (!s.touches) return;
  dContact contacts[kOdeMaxContactsPerPair];
  const int found = dCollide(a, b, kOdeMaxContactsPerPair, &contacts[0].geom, sizeof(dContact));
  for (int k = 0; k < found; ++k) {
    // The pair's restitution and friction on every contact point: ODE takes what is set.
    // With friction, dContactApprox1 bounds each friction row by mu x the point's normal
    // force (without it, by mu newtons, whatever the load). mu2 is left unset, so both
    // rows of the point's pyramid (dPlaneSpace of the normal, ode_contacts.hpp) get mu.
    dSurfaceParameters& surface = contacts[k].surface;
    surface.mode = dContactBounce;
    if (s.friction > 0) surface.mode |= dContactApprox1;
    surface.bounce = s.restitution;
    surface.bounce_vel = self->bounce_vel_;
    surface.mu = s.friction;
    dJointID joint = dJointCreateContact(self->world_, self->joints_, &contacts[k]);
    dJointAttach(joint, dGeomGetBody(a), dGeomGetBody(b));
    ++self->contacts_made_;
  }
}

}  // namespace bb
