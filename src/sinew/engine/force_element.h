// The ForceElement interface: a force model (actuator, spring, muscle, contact, ...) that adds
// loads for a state, may own auxiliary state variables z and inputs, and reports its potential
// energy. How to add a force type: docs/engine.md, "Adding a force".
#pragma once

#include <sinew/math/types.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sinew::engine {

class System;
class Loads;
struct State;
struct DiscreteData;

/// What one force element reads in one evaluation: the system, the state, and the element's
/// own slices of the auxiliary states z and of the inputs (offsets given by System::Finalize).
struct ForceContext {
  const System& system;
  const State& state;
  int z_begin = 0;      ///< first entry of this element's z in State::z
  int input_begin = 0;  ///< first entry of this element's inputs in State::inputs

  /// The element's auxiliary state variable i.
  double z(int i) const;
  /// The element's input i.
  double input(int i) const;
};

/// Where a force element's loads act and what they depend on: bodies (their poses and twists)
/// and coordinates (q and u). Its Jacobian blocks live on these.
struct ForceSupport {
  std::vector<int> bodies;       ///< indices into System::bodies() (not ground)
  std::vector<int> coordinates;  ///< indices into System::coordinates()
};

/// A force model. Stateless itself (a finalized System is shared, read-only, by many threads):
/// everything that changes lives in the State (z, inputs).
class ForceElement {
 public:
  virtual ~ForceElement() = default;

  /// A name, unique among the system's force elements when the element declares state
  /// variables or inputs (their names are "<name>/<variable>").
  virtual std::string name() const { return {}; }

  /// Names of this element's auxiliary state variables (e.g. {"activation",
  /// "fiber_length"}); declared once, when the System is finalized.
  virtual std::vector<std::string> StateVariableNames() const { return {}; }
  /// Names of this element's inputs (e.g. {"excitation"}).
  virtual std::vector<std::string> InputNames() const { return {}; }

  /// Default values of the auxiliary state variables (StateVariableNames().size() entries;
  /// zero unless overridden).
  virtual void SetDefaultStateVariables(Eigen::Ref<VecX> z) const { z.setZero(); }
  /// Called when a default state is made or states are loaded, after the bodies are placed:
  /// may set this element's z from the rest of the state (e.g. muscle-tendon equilibrium).
  /// `z` is this element's slice of state.z. Default: leaves z as it is.
  virtual void InitializeStateVariables(const ForceContext& context, Eigen::Ref<VecX> z) const {
    (void)context, (void)z;
  }
  /// dz/dt of this element's state variables (zdot has StateVariableNames().size() entries).
  virtual void CalcStateVariableDerivatives(const ForceContext& context,
                                            Eigen::Ref<VecX> zdot) const {
    (void)context;
    zdot.setZero();
  }

  /// Adds this element's loads for the context's state to `loads`.
  virtual void AddLoads(const ForceContext& context, Loads& loads) const = 0;

  /// AddLoads and CalcStateVariableDerivatives at one state, which an evaluation needs both of:
  /// an element whose two share their work (a muscle's path and fiber dynamics) does it once.
  /// Default: the two calls.
  virtual void AddLoadsAndStateVariableDerivatives(const ForceContext& context, Loads& loads,
                                                   Eigen::Ref<VecX> zdot) const {
    CalcStateVariableDerivatives(context, zdot);
    AddLoads(context, loads);
  }

  /// The bodies and coordinates the loads act on and depend on, or nullopt when unknown (then
  /// the implicit integrator differentiates the element over every unknown).
  virtual std::optional<ForceSupport> Support() const { return std::nullopt; }
  /// Analytic Jacobian blocks of the element's loads f with respect to position displacements
  /// (K = df/dx) and velocities (D = df/dv), for implicit integration. Rows and columns follow
  /// Support(): per body its twist [w_GB; v_GB] (rows: [torque about Bo; force], in G; columns:
  /// rotation vector and displacement of Bo, in G), then per coordinate its speed (rows:
  /// generalized force). Called only when every coordinate of the support belongs to a
  /// parameterized joint. Return false (the default) to have the engine use central finite
  /// differences of AddLoads over the support instead.
  virtual bool CalcLoadJacobians(const ForceContext& context, Eigen::Ref<MatX> K,
                                 Eigen::Ref<MatX> D) const {
    (void)context, (void)K, (void)D;
    return false;
  }

  /// Labels of the columns this element reports (forces.sto, OpenSim's ForceReporter layout),
  /// fixed once `system` is finalized. Default (from Support(), or every body and coordinate
  /// without one): per body "<name>.<body>.force.X|Y|Z" then "<name>.<body>.torque.X|Y|Z" (the
  /// layout of OpenSim's BushingForce), then per coordinate "<name>.<coordinate>", or "<name>"
  /// alone when that is the element's only column. Override with CalcRecordValues where
  /// OpenSim's layout for the class differs (actuators, springs, ExternalForce).
  virtual std::vector<std::string> RecordLabels(const System& system) const;
  /// Appends the values of RecordLabels(context.system) at the context's state to `values`.
  /// Default: what AddLoads applies, per body the force (N, in G) and the torque about the body
  /// origin (N m, in G), per coordinate the generalized force.
  virtual void CalcRecordValues(const ForceContext& context, std::vector<double>& values) const;

  /// Whether the element carries data from step to step (UpdateDiscreteData); decided when it
  /// is made.
  virtual bool HasDiscreteData() const { return false; }
  /// Called at the end of every accepted step (and never inside a step): the element's data
  /// for the steps that follow, from the state at the step's end (whose `discrete` still holds
  /// the data the step was taken with).
  virtual std::shared_ptr<const DiscreteData> UpdateDiscreteData(
      const ForceContext& context) const {
    (void)context;
    return nullptr;
  }

  /// Potential energy stored in the element (J), zero for non-conservative elements. With it,
  /// CalcMechanicalEnergy covers springs: d/dt (T + V) equals the power of the
  /// non-conservative loads.
  virtual double CalcPotentialEnergy(const ForceContext& context) const {
    (void)context;
    return 0.0;
  }
};

}  // namespace sinew::engine
