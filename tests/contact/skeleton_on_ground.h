// The skeleton-on-ground scene of the NSC test and benchmark: the seed's Rajagopal2015 as
// Chrono's parser simulates it (bodies and joints; its 81 muscles and 20 actuators left out,
// DisableForce) with its collision cylinders (EnableCollision(1, 2)) above a ground plane
// `drop` metres below its lowest cylinder point at the default pose.
#pragma once

#include <sinew/contact/collision_contact_provider.h>
#include <sinew/engine/assemble.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace sinew::testing {

struct SkeletonOnGround {
  std::unique_ptr<engine::System> system;
  engine::State state;            ///< the default pose, at rest
  double ground = 0.0;            ///< the plane's height y (m)
  contact::CollisionModel model;  ///< the collision cylinders
  std::shared_ptr<contact::CollisionContactProvider> provider;
};

inline SkeletonOnGround MakeSkeletonOnGround(double drop,
                                             const contact::NscMaterial& material = {}) {
  SkeletonOnGround scene;
  const model::ModelSpec spec = io::ReadOsim(
      std::string(SINEW_TEST_DATA_DIR) + "/projectchrono/chrono/data/opensim/Rajagopal2015.osim");
  opensim::OpenSimParser parser;
  parser.EnableCollision(1, 2);
  for (const model::ForceSpec& force : spec.forces) parser.DisableForce(force.name);
  scene.system = std::make_unique<engine::System>(spec.gravity);
  parser.ParseSpec(*scene.system, spec);
  scene.system->Finalize();
  scene.state = engine::MakeDefaultState(*scene.system);
  std::vector<Transform> X_GB;
  contact::GatherBodyPoses(scene.state, X_GB);
  scene.model = parser.GetCollisionModel();
  const contact::CollisionModel& model = scene.model;
  double lowest = 1e9;
  for (const contact::CollisionCylinder& c : model.shapes) {
    for (const Vec3& p : {c.p_B_start, c.p_B_end}) {
      lowest = std::min(lowest, (X_GB[c.body] * p).y() - c.radius);
    }
  }
  scene.ground = lowest - drop;
  scene.provider =
      std::make_shared<contact::CollisionContactProvider>(model, scene.ground, material, X_GB);
  return scene;
}

}  // namespace sinew::testing
