// The skeleton-on-ground scene of the contact tests and benchmarks: the seed's Rajagopal2015
// skeleton (bodies, joints, coordinates, gravity: its muscles left out, as in the seed's Chrono
// scene) with the seed's collision cylinders, SMC contact and a ground plane (or box) `drop`
// metres below its lowest cylinder point in the default pose.
#pragma once

#include <sinew/contact/collision_model.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/kinematics/body_depths.h>
#include <sinew/kinematics/forward_kinematics.h>
#include <sinew/kinematics/kinematic_tree.h>
#include <sinew/opensim/parser.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace sinew::testing {

struct SkeletonDrop {
  std::unique_ptr<engine::System> system;
  contact::CollisionModel collision;  ///< the parser's (spec body indices = engine's here)
  double ground_height = 0.0;
  double cylinder_radius = 0.0;
  double total_mass = 0.0;
};

/// `ground_box`: the ground is a box (10 m by 10 m, 1 m thick, its top face at the plane's
/// height, `AddEnvironmentBox`), as in the seed's Chrono scene, instead of the plane.
inline SkeletonDrop MakeSkeletonDrop(double drop, const contact::CollisionMaterial& material = {},
                                     bool ground_box = false) {
  model::ModelSpec spec = io::ReadOsim(std::string(SINEW_TEST_DATA_DIR) +
                                       "/projectchrono/chrono/data/opensim/Rajagopal2015.osim");
  spec.forces.clear();
  // The lowest point of the cylinders in the default pose.
  const contact::CollisionModel cylinders =
      contact::BuildCollisionModel(spec, kinematics::CalcBodyDepths(spec), 1, 2);
  kinematics::KinematicTree tree(spec);
  std::vector<Transform> X_GB(spec.bodies.size());
  kinematics::CalcBodyPoses(tree, tree.default_q(), X_GB);
  double lowest = std::numeric_limits<double>::infinity();
  for (const contact::CollisionCylinder& c : cylinders.shapes) {
    for (const Vec3& p : {c.p_B_start, c.p_B_end})
      lowest = std::min(lowest, (X_GB[c.body] * p).y() - c.radius);
  }
  SkeletonDrop scene;
  scene.ground_height = lowest - drop;
  scene.cylinder_radius = cylinders.shapes.front().radius;
  opensim::OpenSimParser parser;
  parser.EnableCollision();
  parser.SetContactMethod(opensim::ContactMethod::kSmc);
  if (ground_box) {
    parser.AddEnvironmentBox("ground",
                             Transform::Translation(Vec3(0, scene.ground_height - 0.5, 0)),
                             Vec3(5.0, 0.5, 5.0));
  } else {
    parser.SetGroundPlane(scene.ground_height);
  }
  parser.SetContactMaterial(material);
  scene.system = std::make_unique<engine::System>(spec.gravity);
  parser.ParseSpec(*scene.system, spec);
  scene.system->Finalize();
  scene.collision = parser.GetCollisionModel();
  for (const engine::Body& b : scene.system->bodies()) scene.total_mass += b.mass;
  return scene;
}

}  // namespace sinew::testing
