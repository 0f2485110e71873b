// Bullet's soft body as a backend of the spring scenes ("bullet-softbody"): one btSoftBody
// in a btSoftRigidDynamicsWorld, a node per body (anchors of mass 0) and a link per spring.
// A link is a position-based constraint, not a force: its material's m_kLST is the
// fraction of a link's stretch that one solver iteration removes (btSoftBody.cpp,
// PSolve_Links), so the adapter picks the fraction that makes a link act as the case's k.
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "../described_backend.hpp"
#include "bullet_engine.hpp"
#include "bullet_pools.hpp"
#include "bullet_vectors.hpp"
#include "physics/step_start.hpp"
#include "seam/engine_catalogue.hpp"
#include "seam/engine_keys.hpp"
#include "seam/plugin_api.hpp"

namespace bb {

namespace {

/// The link stiffness m_kLST that makes one position iteration act as a spring of
/// stiffness k between nodes of inverse masses summing to `inverse_masses`: the iteration
/// takes the fraction a of the predicted stretch off, which for one link is a backward-Euler
/// step of the pair's relative motion when a = w^2 dt^2 / (1 + w^2 dt^2), w^2 = k (1/m_a + 1/m_b).
double link_stiffness(double k, double inverse_masses, double dt) {
  const double w2dt2 = k * inverse_masses * dt * dt;
  return w2dt2 / (1.0 + w2dt2);
}

/// What the adapter can say of how the soft body stands in for the springs.
constexpr const char* kLinkMapping =
    "one btSoftBody link per spring, rest length the case's; m_kLST = w^2 dt^2 / "
    "(1 + w^2 dt^2), w^2 = k (1/m_a + 1/m_b): one position iteration (piterations = 1) then "
    "moves a lone link exactly as backward Euler moves a spring of stiffness k, which loses "
    "amplitude every step (a factor 1 / sqrt(1 + w^2 dt^2)); in a lattice the links are "
    "projected one after another (Gauss-Seidel), so the match is only approximate";
constexpr const char* kDampingNote =
    "not represented: a link has no damper along it; m_cfg.kDP would damp every node's "
    "absolute velocity (like air), so it stays 0 and the case's spring damping is dropped";

class SoftBodySimulation : public Simulation {
 public:
  SoftBodySimulation(const World& scene, const EngineTables& engines, double dt)
      : scene_(scene), engines_(engines), dt_(dt) {
    world_.setGravity(to_bt(scene.gravity));
    // The soft body takes gravity from its world info, not from the world.
    world_.getWorldInfo().m_gravity = to_bt(scene.gravity);
    world_.getWorldInfo().air_density = 0;
    const std::size_t n = scene.bodies.size();
    std::vector<btVector3> positions(n);
    std::vector<btScalar> masses(n);
    for (std::size_t i = 0; i < n; ++i) {
      positions[i] = to_bt(scene.bodies[i].position);
      masses[i] = scene.bodies[i].fixed ? btScalar(0) : btScalar(scene.bodies[i].mass);
    }
    body_ = std::make_unique<btSoftBody>(&world_.getWorldInfo(), static_cast<int>(n),
                                         positions.data(), masses.data());
    for (std::size_t i = 0; i < n; ++i)
      if (!scene.bodies[i].fixed)
        body_->m_nodes[static_cast<int>(i)].m_v = to_bt(scene.bodies[i].velocity);
    add_links();
    body_->m_cfg.kDP = 0;
    body_->m_cfg.piterations = 1;
    body_->setActivationState(DISABLE_DEACTIVATION);
    world_.addSoftBody(body_.get());
  }
  ~SoftBodySimulation() override { world_.removeSoftBody(body_.get()); }

  void step() override {
    // Impulses due at the start of this step: J / m added to the node's velocity (a point
    // takes no angular impulse, wherever J acts).
    start_.impulses_due([this](const Impulse& imp) {
      btSoftBody::Node& node = body_->m_nodes[imp.body];
      body_->addVelocity(to_bt(imp.impulse) * node.m_im, imp.body);
    });
    world_.stepSimulation(btScalar(dt_), 1, btScalar(dt_));
  }

  void read(State& out) const override {
    for (std::size_t i = 0; i < out.size(); ++i) {
      const btSoftBody::Node& node = body_->m_nodes[static_cast<int>(i)];
      out[i] = {from_bt(node.m_x), from_bt(node.m_v), Quat::Identity(), Vec3::Zero()};
    }
  }

  Settings settings() const override {
    using S = std::string;
    Settings s = engine_key_settings(engines_, bullet_description());
    s.push_back({"precision", sizeof(btScalar) == 8 ? S("double") : S("float")});
    s.push_back({"step", S("btSoftRigidDynamicsWorld::stepSimulation(dt, 1, dt): one fixed "
                           "substep")});
    s.push_back({"sleeping", false});
    s.push_back({"deactivation", S("setActivationState(DISABLE_DEACTIVATION) on the soft body")});
    s.push_back({"springs", S(kLinkMapping)});
    s.push_back({"spring_damping", S(kDampingNote)});
    s.push_back({"spring_stiffness_limit",
                 S("none: m_kLST < 1 for every k; a stiff link takes off nearly all its "
                   "stretch each step, as a rigid rod would")});
    s.push_back({"link_stiffness_min", kLST_min_});
    s.push_back({"link_stiffness_max", kLST_max_});
    if (!scene_.impulses.empty())
      s.push_back({"impulse", S("btSoftBody::addVelocity(J / m, node) before the step that "
                                "starts at its time")});
    s.push_back({"nodes", S("a node per body, mass the body's, anchors mass 0; bodies are "
                            "points (no shape, no spin)")});
    return s;
  }

 private:
  /// A link per spring whose ends are not both anchors, with its material and rest length.
  void add_links() {
    std::map<double, btSoftBody::Material*> materials;
    for (const Spring& spring : scene_.springs) {
      const btSoftBody::Node& a = body_->m_nodes[spring.body_a];
      const btSoftBody::Node& b = body_->m_nodes[spring.body_b];
      const double inverse_masses = double(a.m_im) + double(b.m_im);
      if (inverse_masses == 0.0) continue;
      const double k_lst = link_stiffness(spring.stiffness, inverse_masses, dt_);
      btSoftBody::Material*& material = materials[k_lst];
      if (material == nullptr) {
        material = body_->appendMaterial();
        material->m_kLST = btScalar(k_lst);
      }
      body_->appendLink(spring.body_a, spring.body_b, material);
      kLST_min_ = body_->m_links.size() == 1 ? k_lst : std::min(kLST_min_, k_lst);
      kLST_max_ = std::max(kLST_max_, k_lst);
    }
    // Bullet's constants, then the case's rest lengths over the distances it takes.
    body_->updateConstants();
    int link = 0;
    for (const Spring& spring : scene_.springs) {
      const double inverse_masses =
          double(body_->m_nodes[spring.body_a].m_im) + double(body_->m_nodes[spring.body_b].m_im);
      if (inverse_masses == 0.0) continue;
      btSoftBody::Link& l = body_->m_links[link++];
      l.m_rl = btScalar(spring.rest_length);
      l.m_c1 = l.m_rl * l.m_rl;
    }
    // Else the first step's predictMotion would reset the rest lengths to the distances.
    body_->m_bUpdateRtCst = false;
  }

  const World& scene_;
  const EngineTables& engines_;  ///< the case's [engines.bullet] table among the others
  double dt_;
  btSoftBodyRigidBodyCollisionConfiguration configuration_{pools_for(scene_)};
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btSoftRigidDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  std::unique_ptr<btSoftBody> body_;
  double kLST_min_ = 0.0, kLST_max_ = 0.0;
  /// Impulses due (its links are the springs, and it takes no other force).
  StepStart start_{scene_, dt_, {false}};
};

}  // namespace

DeclaredBackend::Start bullet_softbody_start() {
  return start_engine<SoftBodySimulation>();
}

}  // namespace bb
