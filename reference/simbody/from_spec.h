// A Sinew ModelSpec (skeleton, couplers) and start state as input for the Simbody reference
// (simbody_model.h): each joint gets the mobilizer OpenSim gives it in Simbody, a CustomJoint a
// MobilizedBody::FunctionBased (its axes, its functions of the joint's coordinates), a PinJoint
// a Pin, SliderJoint a Slider, UniversalJoint a Universal, GimbalJoint a Gimbal, BallJoint a
// Ball, FreeJoint a Free, PlanarJoint a Planar, EllipsoidJoint an Ellipsoid, a WeldJoint or a
// joint whose coordinates are all locked a Weld (at the start pose); a
// CoordinateCouplerConstraint a Constraint::CoordinateCoupler. The axis functions are Sinew's,
// called through SimTK::Function without allocating.
#pragma once

#include <sinew/common/error.h>
#include <sinew/engine/state.h>
#include <sinew/math/transform.h>
#include <sinew/model/model_spec.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "simbody/simbody_model.h"

namespace simbody_reference {

using sinew::model::JointSpec;
using sinew::model::JointType;
using sinew::model::ModelSpec;

namespace detail {

inline std::array<double, 3> ToArray(const sinew::Vec3& v) { return {v.x(), v.y(), v.z()}; }

inline std::array<double, 9> ToArray(const sinew::Mat3& m) {
  std::array<double, 9> a;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a[3 * i + j] = m(i, j);
  }
  return a;
}

inline Pose ToPose(const sinew::Transform& X) { return {ToArray(X.R), ToArray(X.p)}; }

// A Sinew function of the arguments in x (none for a Constant axis), or its partial derivative
// by the arguments listed in wrt.
inline ScalarFunction Wrap(sinew::functions::FunctionPtr f) {
  return [f](const double* x, int n, const int* wrt, int num_wrt) {
    if (n == 0) return num_wrt == 0 ? f->Calc(0.0) : 0.0;
    const std::span<const double> args(x, n);
    return num_wrt == 0 ? f->CalcN(args)
                        : f->CalcPartialN(args, std::span<const int>(wrt, num_wrt));
  };
}

inline bool AllLocked(const ModelSpec& spec, const JointSpec& joint) {
  return !joint.coordinates.empty() &&
         std::all_of(joint.coordinates.begin(), joint.coordinates.end(),
                     [&](int c) { return spec.coordinates[c].locked; });
}

// `reversed`: the joint's child is the body nearer to ground.
inline Joint ToJoint(const ModelSpec& spec, const JointSpec& joint,
                     const sinew::engine::State& start, bool reversed) {
  using Kind = Joint::Kind;
  Joint out;
  out.parent = joint.parent_body;
  out.child = joint.child_body;
  out.X_PF = ToPose(joint.X_PF);
  out.X_BM = ToPose(joint.X_BM);
  if (AllLocked(spec, joint)) {
    // Welded at the start's relative pose: the cheapest lock in Simbody.
    const auto pose = [&](int body) {
      const sinew::engine::BodyState& b = start.bodies[body];
      return sinew::Transform(b.quat_GB.toRotationMatrix(), b.p_GB);
    };
    out.kind = Kind::kWeld;
    out.X_PF = ToPose(pose(joint.parent_body).Inverse() * pose(joint.child_body));
    out.X_BM = Pose();
    out.reversed = reversed;
    return out;
  }
  out.reversed = reversed;
  out.coordinates = joint.coordinates;
  for (int c : joint.coordinates) {
    if (spec.coordinates[c].prescribed) {
      throw sinew::Error("simbody reference: prescribed coordinate '" + spec.coordinates[c].name +
                         "'");
    }
  }
  switch (joint.kind) {
    case JointType::kPin:
      out.kind = Kind::kPin;
      break;
    case JointType::kSlider:
      out.kind = Kind::kSlider;
      break;
    case JointType::kUniversal:
      out.kind = Kind::kUniversal;
      break;
    case JointType::kGimbal:
      out.kind = Kind::kGimbal;
      break;
    case JointType::kBall:
      out.kind = Kind::kBall;
      break;
    case JointType::kFree:
      out.kind = Kind::kFree;
      break;
    case JointType::kPlanar:
      out.kind = Kind::kPlanar;
      break;
    case JointType::kEllipsoid: {
      out.kind = Kind::kEllipsoid;
      const auto radii = joint.parameters.find("radii_x_y_z");
      if (radii == joint.parameters.end() || radii->second.size() != 3) {
        throw sinew::Error("simbody reference: ellipsoid joint '" + joint.name +
                           "' without radii_x_y_z");
      }
      out.radii = {radii->second[0], radii->second[1], radii->second[2]};
      break;
    }
    case JointType::kWeld:
      out.kind = Kind::kWeld;
      break;
    case JointType::kCustom:
      out.kind = Kind::kFunctionBased;
      for (const sinew::model::TransformAxisSpec& axis : joint.spatial_transform) {
        Axis a;
        a.f = Wrap(axis.function);
        a.axis = ToArray(axis.axis.normalized());
        for (int c : axis.coordinates) {
          const auto at = std::find(joint.coordinates.begin(), joint.coordinates.end(), c);
          a.arguments.push_back(static_cast<int>(at - joint.coordinates.begin()));
        }
        out.axes.push_back(std::move(a));
      }
      break;
    default:
      throw sinew::Error("simbody reference: joint '" + joint.name + "' of type " + joint.type +
                         " has no Simbody counterpart here");
  }
  return out;
}

}  // namespace detail

/// `spec`'s skeleton as Simbody input: its bodies, its joints from ground outwards (a joint
/// whose parent hangs from its child as Simbody's reverse mobilizer; one whose coordinates are
/// all locked welded at `start`'s pose), its CoordinateCouplerConstraints, at
/// `start`'s coordinates and speeds (`start` is a Sinew State of the System built from `spec`,
/// whose coordinates are the spec's); other locked coordinates held by Simbody's
/// ConstantCoordinate. Throws sinew::Error for what has no counterpart here: ScapulothoracicJoint,
/// ConstantCurvatureJoint and unknown joints, prescribed coordinates,
/// constraints other than CoordinateCouplerConstraint. Forces are not carried over (gravity
/// is), nor constraints when `with_constraints` is false (for a System made by BuildSystem).
inline Model ToSimbody(const ModelSpec& spec, const sinew::engine::State& start,
                       bool with_constraints = true) {
  Model model;
  model.gravity = detail::ToArray(spec.gravity);
  for (const sinew::model::BodySpec& b : spec.bodies) {
    model.bodies.push_back({b.mass, detail::ToArray(b.mass_center), detail::ToArray(b.inertia)});
  }
  std::vector<bool> placed(spec.bodies.size(), false);
  placed[sinew::model::kGroundIndex] = true;
  std::vector<bool> used(spec.joints.size(), false);
  for (size_t done = 0; done < spec.joints.size();) {
    const size_t before = done;
    for (size_t j = 0; j < spec.joints.size(); ++j) {
      const JointSpec& joint = spec.joints[j];
      if (used[j] || placed[joint.child_body] == placed[joint.parent_body]) continue;
      used[j] = true;
      // A joint whose parent hangs from its child is built in reverse, as OpenSim does.
      const bool reversed = placed[joint.child_body];
      model.joints.push_back(detail::ToJoint(spec, joint, start, reversed));
      if (!detail::AllLocked(spec, joint)) {
        for (int c : joint.coordinates) {
          if (spec.coordinates[c].locked) model.locked.push_back(c);
        }
      }
      placed[reversed ? joint.parent_body : joint.child_body] = true;
      ++done;
    }
    if (done == before) {
      for (size_t j = 0; j < spec.joints.size(); ++j) {
        if (!used[j] && placed[spec.joints[j].child_body] && placed[spec.joints[j].parent_body]) {
          throw sinew::Error("simbody reference: joint '" + spec.joints[j].name +
                             "' closes a loop (no loop constraints here)");
        }
      }
      throw sinew::Error("simbody reference: a joint connects two bodies not connected to ground");
    }
  }
  for (const sinew::model::ConstraintSpec& c : spec.constraints) {
    if (!c.enabled || !with_constraints) continue;
    if (c.type != "CoordinateCouplerConstraint") {
      throw sinew::Error("simbody reference: constraint '" + c.name + "' of type " + c.type +
                         " has no Simbody counterpart here");
    }
    if (!c.function) {
      throw sinew::Error("simbody reference: coupler '" + c.name + "' without a function");
    }
    // OpenSim's form: scale * f(q_independent) - q_dependent = 0.
    const int n = static_cast<int>(c.independent_coordinates.size());
    const sinew::functions::FunctionPtr f = c.function;
    const double scale = c.scale_factor;
    Coupler coupler;
    coupler.coordinates = c.independent_coordinates;
    coupler.coordinates.push_back(c.dependent_coordinate);
    coupler.f = [f, n, scale](const double* x, int, const int* wrt, int num_wrt) {
      const std::span<const double> independent(x, n);
      if (num_wrt == 0) return scale * f->CalcN(independent) - x[n];
      if (std::find(wrt, wrt + num_wrt, n) != wrt + num_wrt) return num_wrt == 1 ? -1.0 : 0.0;
      return scale * f->CalcPartialN(independent, std::span<const int>(wrt, num_wrt));
    };
    model.couplers.push_back(std::move(coupler));
  }
  model.q.assign(start.q.data(), start.q.data() + start.q.size());
  model.u.assign(start.u.data(), start.u.data() + start.u.size());
  return model;
}

/// The largest |a_i - b_i| (the coordinates of the two engines, in spec order).
inline double MaxDifference(const std::vector<double>& a, const Eigen::VectorXd& b) {
  double d = 0.0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[static_cast<int>(i)]));
  return d;
}

}  // namespace simbody_reference
