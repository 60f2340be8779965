#include <sinew/common/error.h>
#include <sinew/kinematics/custom_joint_model.h>
#include <sinew/kinematics/euler_joint_models.h>
#include <sinew/kinematics/joint_model.h>
#include <sinew/kinematics/scapulothoracic_joint_model.h>

#include <array>
#include <string>

namespace sinew::kinematics {
namespace {

using Kind = TransformAxisTerm::Kind;

[[noreturn]] void Fail(const model::JointSpec& joint, const std::string& message) {
  throw Error(joint.where, joint.path.empty() ? joint.name : joint.path, message);
}

TransformAxisTerm Fixed(const Vec3& axis) {
  TransformAxisTerm t;
  t.kind = Kind::kConstant;
  t.axis = axis;
  return t;
}

TransformAxisTerm Free(const Vec3& axis, int local_coordinate) {
  TransformAxisTerm t;
  t.kind = Kind::kIdentity;
  t.axis = axis;
  t.args = {local_coordinate};
  return t;
}

void RequireCoordinates(const model::JointSpec& joint, int n) {
  if (static_cast<int>(joint.coordinates.size()) != n) {
    Fail(joint, joint.type + " needs " + std::to_string(n) + " coordinate(s), the model gives " +
                    std::to_string(joint.coordinates.size()));
  }
}

// A numeric parameter of `joint` with `size` values; the first of `names` that is present.
std::vector<double> Parameter(const model::JointSpec& joint,
                              std::initializer_list<const char*> names, size_t size) {
  for (const char* name : names) {
    auto it = joint.parameters.find(name);
    if (it == joint.parameters.end()) continue;
    if (it->second.size() != size) {
      Fail(joint, std::string(name) + " needs " + std::to_string(size) + " value(s)");
    }
    return it->second;
  }
  Fail(joint, std::string("missing property ") + *names.begin());
}

// TransformAxis -> term, with the axis' coordinates mapped to joint-local indices.
TransformAxisTerm MakeCustomTerm(const model::JointSpec& joint,
                                 const model::TransformAxisSpec& axis_spec) {
  TransformAxisTerm t;
  t.axis = axis_spec.axis;
  if (!(t.axis.norm() > 0.0)) Fail(joint, axis_spec.name + ": zero axis");
  if (!axis_spec.function) Fail(joint, axis_spec.name + ": no function");
  t.function = axis_spec.function;
  for (int global : axis_spec.coordinates) {
    int local = -1;
    for (size_t k = 0; k < joint.coordinates.size(); ++k) {
      if (joint.coordinates[k] == global) local = static_cast<int>(k);
    }
    if (local < 0) Fail(joint, axis_spec.name + ": uses a coordinate that is not the joint's");
    t.args.push_back(local);
  }
  const int n = static_cast<int>(t.args.size());
  if (n == 0) {
    t.kind = Kind::kConstant;
    if (t.function->TypeName() == "LinearFunction") {
      // OpenSim evaluates an axis without coordinates through SimTK::Function::Linear with an
      // empty argument vector, which returns coefficients[0]: the slope, not the intercept.
      t.value = t.function->CalcDerivative(0.0, 1);
    } else {
      // Constant (and MultiplierFunction of a Constant) ignore the argument; the corpus has no
      // other function on an axis without coordinates.
      const double zero[1] = {0.0};
      t.value = t.function->CalcN(zero);
    }
  } else if (n == 1) {
    if (t.function->NumArguments() != 1) {
      Fail(joint, axis_spec.name + ": function of " + std::to_string(t.function->NumArguments()) +
                      " arguments given 1 coordinate");
    }
    t.kind = Kind::kFunction1;
  } else {
    if (t.function->NumArguments() != n) {
      Fail(joint, axis_spec.name + ": function of " + std::to_string(t.function->NumArguments()) +
                      " arguments given " + std::to_string(n) + " coordinates");
    }
    t.kind = Kind::kFunctionN;
  }
  return t;
}

std::unique_ptr<JointModel> MakeCustom(const model::JointSpec& joint) {
  if (joint.spatial_transform.size() != 6) {
    Fail(joint, "CustomJoint needs a SpatialTransform with 6 axes");
  }
  std::array<TransformAxisTerm, 6> axes;
  for (int i = 0; i < 6; ++i) axes[i] = MakeCustomTerm(joint, joint.spatial_transform[i]);
  // OpenSim rejects (nearly) collinear axes within the rotation and translation triples.
  for (int base : {0, 3}) {
    for (int i = base; i < base + 3; ++i) {
      for (int j = i + 1; j < base + 3; ++j) {
        if (axes[i].axis.normalized().cross(axes[j].axis.normalized()).norm() < 1e-5) {
          Fail(joint, joint.spatial_transform[i].name + " and " + joint.spatial_transform[j].name +
                          " are collinear");
        }
      }
    }
  }
  return std::make_unique<CustomJointModel>(std::move(axes),
                                            static_cast<int>(joint.coordinates.size()));
}

}  // namespace

std::unique_ptr<JointModel> MakeJointModel(const model::ModelSpec& spec, int joint_index) {
  if (joint_index < 0 || joint_index >= static_cast<int>(spec.joints.size())) {
    throw Error("MakeJointModel: joint index out of range");
  }
  const model::JointSpec& joint = spec.joints[joint_index];
  if (!IsJointTypeModeled(joint.kind)) {
    Fail(joint, "joint type " + joint.type + " is not supported by the kinematics");
  }
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
  switch (joint.kind) {
    case model::JointType::kPin:
      RequireCoordinates(joint, 1);
      return std::make_unique<CustomJointModel>(
          std::array<TransformAxisTerm, 6>{Free(z, 0), Fixed(x), Fixed(y), Fixed(x), Fixed(y),
                                           Fixed(z)},
          1);
    case model::JointType::kSlider:
      RequireCoordinates(joint, 1);
      return std::make_unique<CustomJointModel>(
          std::array<TransformAxisTerm, 6>{Fixed(x), Fixed(y), Fixed(z), Free(x, 0), Fixed(y),
                                           Fixed(z)},
          1);
    case model::JointType::kUniversal:
      RequireCoordinates(joint, 2);
      return std::make_unique<CustomJointModel>(
          std::array<TransformAxisTerm, 6>{Free(x, 0), Free(y, 1), Fixed(z), Fixed(x), Fixed(y),
                                           Fixed(z)},
          2);
    case model::JointType::kGimbal:
      RequireCoordinates(joint, 3);
      return std::make_unique<CustomJointModel>(
          std::array<TransformAxisTerm, 6>{Free(x, 0), Free(y, 1), Free(z, 2), Fixed(x), Fixed(y),
                                           Fixed(z)},
          3);
    case model::JointType::kPlanar:
      RequireCoordinates(joint, 3);
      return std::make_unique<CustomJointModel>(
          std::array<TransformAxisTerm, 6>{Free(z, 0), Fixed(x), Fixed(y), Free(x, 1), Free(y, 2),
                                           Fixed(z)},
          3);
    case model::JointType::kBall:
      RequireCoordinates(joint, 3);
      return std::make_unique<BallJointModel>();
    case model::JointType::kFree:
      RequireCoordinates(joint, 6);
      return std::make_unique<FreeJointModel>();
    case model::JointType::kEllipsoid: {
      RequireCoordinates(joint, 3);
      const std::vector<double> r = Parameter(joint, {"radii_x_y_z"}, 3);
      return std::make_unique<EllipsoidJointModel>(Vec3(r[0], r[1], r[2]));
    }
    case model::JointType::kWeld:
      RequireCoordinates(joint, 0);
      return std::make_unique<WeldJointModel>();
    case model::JointType::kScapulothoracic: {
      RequireCoordinates(joint, 4);
      const std::vector<double> r = Parameter(joint, {"thoracic_ellipsoid_radii_x_y_z"}, 3);
      const std::vector<double> o = Parameter(joint, {"scapula_winging_axis_origin"}, 2);
      const std::vector<double> d = Parameter(joint, {"scapula_winging_axis_direction"}, 1);
      return std::make_unique<ScapulothoracicJointModel>(Vec3(r[0], r[1], r[2]), o[0], o[1], d[0]);
    }
    case model::JointType::kCustom:
      return MakeCustom(joint);
    case model::JointType::kConstantCurvature:
    case model::JointType::kUnknown:
      break;  // refused above
  }
  Fail(joint, "joint type " + joint.type + " is not supported by the kinematics");
}

bool IsJointTypeModeled(model::JointType kind) {
  return kind != model::JointType::kConstantCurvature && kind != model::JointType::kUnknown;
}

}  // namespace sinew::kinematics
