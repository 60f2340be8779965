#include <sinew/kinematics/joint_model.h>
#include <sinew/opensim/build_system.h>
#include <sinew/opensim/internal/constraint_registry.h>
#include <sinew/opensim/support.h>

#include <cmath>
#include <string>
#include <vector>

namespace sinew::opensim {
namespace {

engine::JointForm DirectForm(model::JointType type) {
  switch (type) {
    case model::JointType::kPin:
      return engine::JointForm::kPin;
    case model::JointType::kBall:
      return engine::JointForm::kBall;
    case model::JointType::kUniversal:
      return engine::JointForm::kUniversal;
    case model::JointType::kWeld:
      return engine::JointForm::kWeld;
    default:
      return engine::JointForm::kParameterized;
  }
}

void Note(Diagnostics* notes, const SourceLocation& where, const std::string& component,
          const std::string& message) {
  if (notes) notes->push_back({where, component, message});
}

// Per spec coordinate: whether a simulated constraint uses its speed (then its joint must be
// parameterized: the engine refuses constraints on coordinates of direct joints).
std::vector<bool> ConstrainedCoordinates(const model::ModelSpec& spec) {
  std::vector<bool> used(spec.coordinates.size(), false);
  for (const model::ConstraintSpec& c : spec.constraints) {
    if (!IsConstraintSimulated(c)) continue;
    for (int k : internal::FindConstraintType(c.type)->coordinates(c)) used[k] = true;
  }
  return used;
}

// Per spec coordinate: whether OpenSim's assembler leaves it free to satisfy the constraints
// (no goal to keep its default): is_free_to_satisfy_constraints, or the dependent coordinate
// of an enforced CoordinateCouplerConstraint (OpenSim's Coordinate::isDependent).
std::vector<bool> DependentCoordinates(const model::ModelSpec& spec) {
  std::vector<bool> dependent(spec.coordinates.size(), false);
  for (size_t c = 0; c < spec.coordinates.size(); ++c) {
    dependent[c] = spec.coordinates[c].free_to_satisfy_constraints;
  }
  for (const model::ConstraintSpec& c : spec.constraints) {
    if (c.type == "CoordinateCouplerConstraint" && IsConstraintSimulated(c) &&
        c.dependent_coordinate != model::kNone) {
      dependent[c.dependent_coordinate] = true;
    }
  }
  return dependent;
}

}  // namespace

SpecToSystem BuildInto(const model::ModelSpec& spec, engine::System& system,
                       const BuildOptions& options, Diagnostics* notes) {
  if (spec.bodies.empty()) throw Error({spec.file, 0}, "/ground", "the model has no ground");
  SpecToSystem map;
  map.bodies.assign(spec.bodies.size(), 0);
  map.coordinates.assign(spec.coordinates.size(), model::kNone);
  for (size_t b = 1; b < spec.bodies.size(); ++b) {
    const model::BodySpec& body = spec.bodies[b];
    if (!(body.mass >= 0.0) || !std::isfinite(body.mass)) {
      throw Error(body.where, body.path, "body mass must be finite and >= 0");
    }
    engine::Body e;
    e.name = body.name;
    e.mass = body.mass;
    e.p_BCm = body.mass_center;
    e.I_Bcm_B = body.inertia;
    try {
      map.bodies[b] = system.AddBody(e);
    } catch (const Error& error) {
      throw Error(body.where, body.path, error.message());
    }
  }
  const std::vector<bool> coupled = ConstrainedCoordinates(spec);
  const std::vector<bool> dependent = DependentCoordinates(spec);
  for (size_t j = 0; j < spec.joints.size(); ++j) {
    const model::JointSpec& joint = spec.joints[j];
    std::vector<engine::CoordinateDesc> coordinates;
    bool constrained_coordinate = false;
    for (int c : joint.coordinates) {
      constrained_coordinate = constrained_coordinate || coupled[c];
      const model::CoordinateSpec& cs = spec.coordinates[c];
      engine::CoordinateDesc d;
      d.name = cs.name;
      d.default_value = cs.default_value;
      d.default_speed = cs.default_speed_value;
      d.assembly_weight = dependent[c] ? 0.0 : 1.0;
      if (cs.prescribed && cs.prescribed_function) {
        d.motion = engine::CoordinateMotion::kPrescribed;
        d.prescribed = cs.prescribed_function;
      } else if (cs.locked) {
        d.motion = engine::CoordinateMotion::kLocked;
      }
      if (cs.prescribed && !cs.prescribed_function) {
        Note(notes, cs.where, cs.path, "prescribed without a prescribed_function: left free");
      }
      constrained_coordinate =
          constrained_coordinate || d.motion != engine::CoordinateMotion::kFree;
      coordinates.push_back(std::move(d));
    }
    engine::JointForm form = DirectForm(joint.kind);
    if (!options.direct_joints || constrained_coordinate) form = engine::JointForm::kParameterized;
    try {
      std::shared_ptr<const kinematics::JointModel> model =
          kinematics::MakeJointModel(spec, static_cast<int>(j));
      const int engine_joint = system.AddJoint(joint.name, map.bodies[joint.parent_body],
                                               joint.X_PF, map.bodies[joint.child_body], joint.X_BM,
                                               form, std::move(model), coordinates);
      map.joints.push_back(engine_joint);
      for (size_t k = 0; k < joint.coordinates.size(); ++k) {
        map.coordinates[joint.coordinates[k]] = system.joints()[engine_joint].coordinates[k];
      }
    } catch (const Error& error) {
      if (!error.where().file.empty()) throw;
      throw Error(joint.where, joint.path, error.message());
    }
  }
  return map;
}

std::unique_ptr<engine::System> BuildSystem(const model::ModelSpec& spec,
                                            const BuildOptions& options, Diagnostics* notes) {
  auto system = std::make_unique<engine::System>(spec.gravity);
  BuildInto(spec, *system, options, notes);
  for (const model::ConstraintSpec& c : spec.constraints) {
    if (c.enabled) Note(notes, c.where, c.path, c.type + " is not simulated by the skeleton build");
  }
  for (const model::ForceSpec& f : spec.forces) {
    if (f.applies_force)
      Note(notes, f.where, f.path, f.type + " is not simulated by the skeleton build");
  }
  for (const model::ContactGeometrySpec& g : spec.contact_geometry) {
    Note(notes, g.where, g.name,
         g.type + " contact geometry is not simulated by the skeleton build");
  }
  try {
    system->Finalize();
  } catch (const Error& error) {
    throw Error({spec.file, error.where().line}, error.component(), error.message());
  }
  return system;
}

}  // namespace sinew::opensim
