// The contacts table of an NSC run (contact::NscContactTable): the stepper's impulses divided by
// its step, per body and per body pair, against Coulomb's closed form for a sliding block.
#include <gtest/gtest.h>
#include <sinew/contact/nsc_contact_table.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/nsc_integrator.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "contact/contact_models.h"

namespace sinew::contact {
namespace {

constexpr double kG = 9.80665;

// The column `label` of `row` (labels in table order).
double Column(const NscContactTable& table, const std::vector<double>& row,
              const std::string& label) {
  const auto& labels = table.labels();
  const auto it = std::find(labels.begin(), labels.end(), label);
  if (it == labels.end()) throw Error("no column " + label);
  return row[it - labels.begin()];
}
Vec3 Column3(const NscContactTable& table, const std::vector<double>& row,
             const std::string& prefix) {
  return {Column(table, row, prefix + ".X"), Column(table, row, prefix + ".Y"),
          Column(table, row, prefix + ".Z")};
}

TEST(NscContactTableTest, SlidingBlockReportsItsWeightAndCoulombFriction) {
  // A 1 kg box (0.2 x 0.1 x 0.2 m, a collision box on the body) resting on the ground plane,
  // launched along x at 2 m/s, mu = 0.5: while it slides (until v0 / (mu g) = 0.41 s) each
  // step's impulse is m g h up and mu m g h back, so the table reports the force (-mu m g,
  // m g, 0) on the block, its opposite on ground, and no torque about the block's centre (it
  // slides without turning: the corners' normal impulses balance the friction's moment). The
  // solver's tolerance (1e-12 m/s) bounds the impulse errors by m 1e-12 m/s, 1e-9 N at h = 1 ms.
  // The same on a ground box whose top face is y = 0 (Bullet's box-box detector: a face's
  // corners), on a flat ground mesh of two triangles (the corners over them), and as a closed
  // cube mesh (a ContactMesh, colliding as its hull) on that ground mesh and on the box.
  constexpr double kMass = 1.0, kMu = 0.5, kH = 1e-3, kV0 = 2.0;
  for (const std::string ground :
       {"plane", "box", "mesh", "mesh, the block a mesh", "box, the block a mesh"}) {
    SCOPED_TRACE("on the ground " + ground);
    auto system =
        testing::ParseContactModel(testing::FreeBodyContactModel(kMass, Vec3(0.004, 0.008, 0.004),
                                                                 Vec3(0, -kG, 0), 0.1, {}, ""),
                                   "block.osim");
    CollisionModel model;
    CollisionGeometry box;
    box.name = "block";
    box.kind = CollisionShapeKind::kBox;
    box.body = 1;
    box.half_extents = Vec3(0.1, 0.05, 0.1);
    if (ground.ends_with("the block a mesh")) {
      box.kind = CollisionShapeKind::kTriangleMesh;
      box.mesh = testing::MakeBoxMesh(box.half_extents);
    }
    model.geometry.push_back(box);
    if (ground.starts_with("mesh")) {  // a flat square of two triangles
      auto mesh = std::make_shared<ShapeMesh>();
      mesh->vertices = {Vec3(-3, 0, -1), Vec3(3, 0, -1), Vec3(3, 0, 1), Vec3(-3, 0, 1)};
      mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
      CollisionGeometry floor;
      floor.name = "floor";
      floor.kind = CollisionShapeKind::kTriangleMesh;
      floor.mesh = mesh;
      model.geometry.push_back(floor);
    } else if (ground.starts_with("box")) {
      CollisionGeometry floor = box;
      floor.name = "floor";
      floor.kind = CollisionShapeKind::kBox;
      floor.mesh = nullptr;
      floor.body = 0;
      floor.X_BS = Transform::Translation(Vec3(0, -0.5, 0));
      floor.half_extents = Vec3(3.0, 0.5, 1.0);
      model.geometry.push_back(floor);
    } else {
      AddGroundPlane(model, 0.0);
    }
    auto provider = std::make_shared<CollisionContactProvider>(
        model, std::nullopt, NscMaterial{.friction = kMu, .restitution = 0.0});
    engine::IntegratorSettings settings;
    settings.step = kH;
    engine::NscSettings nsc;
    nsc.solver.max_iterations = 1000;
    nsc.solver.tolerance = 1e-12;
    engine::NscIntegrator integrator(*system, provider, settings, nsc);
    const NscContactTable table(*system, integrator, *provider);
    // ground, body; all; ground-body; the solver's iterations, residual, unconverged steps
    ASSERT_EQ(table.labels().size(), 2u * 6u + 1u + 1u + 3u);
    engine::State state = engine::MakeDefaultState(*system);
    engine::SetCoordinateValue(*system, state, "ty", 0.05);
    engine::SetCoordinateSpeed(*system, state, "tx", kV0);
    std::vector<double> row;
    table.Row(row);
    for (const double value : row) EXPECT_EQ(value, 0.0) << "before the first step";
    integrator.StepTo(state, 0.1 - kH);
    const Vec3 origin = state.bodies[1].p_GB;  // the block's centre at the last step's start
    integrator.StepTo(state, 0.1);
    table.Row(row);
    const Vec3 force = Column3(table, row, "nsc_contact.body.force");
    const Vec3 torque = Column3(table, row, "nsc_contact.body.torque");
    const double tolerance = 1e-8;  // 10 x the solver's bound, for the four corners
    EXPECT_NEAR(force.x(), -kMu * kMass * kG, tolerance);
    EXPECT_NEAR(force.y(), kMass * kG, tolerance);
    EXPECT_NEAR(force.z(), 0.0, tolerance);
    EXPECT_NEAR(torque.norm(), 0.0, tolerance);
    // Ground: the opposite force; its torque about ground's origin is that of the opposite force
    // at the block's centre (the block's own torque being zero).
    const Vec3 ground_force = Column3(table, row, "nsc_contact.ground.force");
    const Vec3 ground_torque = Column3(table, row, "nsc_contact.ground.torque");
    EXPECT_NEAR((ground_force + force).norm(), 0.0, 1e-12);
    EXPECT_NEAR((ground_torque - origin.cross(-force)).norm(), 0.0, tolerance);
    // Three or four corners carry it (two cannot balance both moments).
    const double active = Column(table, row, "nsc_contact.active_contacts");
    EXPECT_GE(active, 3.0);
    EXPECT_LE(active, 4.0);
    EXPECT_EQ(Column(table, row, "nsc_contact.ground-body.active_contacts"), active);
    EXPECT_GT(state.bodies[1].v_GB.x(), 1.0) << "still sliding";
    // The solver's columns: the last step's solve and the count of solves so far that stopped
    // above the tolerance (the solver's own test: final residual > tolerance).
    EXPECT_EQ(Column(table, row, "nsc_contact.solver_iterations"),
              integrator.last_step().iterations);
    EXPECT_EQ(Column(table, row, "nsc_contact.solver_residual"), integrator.last_step().residual);
    EXPECT_EQ(Column(table, row, "nsc_contact.unconverged_steps"),
              static_cast<double>(integrator.solve_summary().unconverged));
    EXPECT_LE(integrator.solve_summary().most_iterations, nsc.solver.max_iterations);
    EXPECT_EQ(integrator.solve_summary().unconverged > 0,
              integrator.solve_summary().worst_residual > nsc.solver.tolerance);
    std::cout << "nsc table: sliding block force " << force.transpose() << " N (closed form "
              << -kMu * kMass * kG << " " << kMass * kG << " 0), torque " << torque.transpose()
              << " N m, " << active << " active contacts ("
              << "on the ground " << ground << ")\n";
  }
}

}  // namespace
}  // namespace sinew::contact
