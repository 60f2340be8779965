// Unilateral contact rows, declared in the engine so that a contact method can add them
// without the engine knowing where they come from: a ContactProvider (implemented by the
// contact layer, or by anyone) lists, for the body poses of a state, the points where two
// bodies touch or nearly touch. The NSC stepper (nsc_integrator.h) turns each into three
// velocity rows (one normal, two tangential) with bounds: a normal impulse >= 0 and a
// tangential impulse inside the Coulomb cone of radius friction * normal impulse.
#pragma once

#include <sinew/math/types.h>

#include <vector>

namespace sinew::engine {

class System;
struct State;

/// One contact point between bodies `body1` and `body2` (indices into System::bodies(); either
/// may be ground, 0). `n_G` is the unit normal in G pointing from body1 towards body2: the gap
/// grows when body2's point moves along +n_G relative to body1's. `depth` is the overlap along
/// n_G (m): > 0 when the shapes interpenetrate, < 0 when a gap of -depth is still open (a
/// contact found within an envelope, so that the stepper can stop the bodies where they meet).
struct UnilateralContact {
  int body1 = 0;
  int body2 = 0;
  /// The contact point, in G (m): midway between the two surfaces' nearest points, which are
  /// p_G + depth/2 n_G on body1 and p_G - depth/2 n_G on body2 (where the gap closes or the
  /// overlap ends). The NSC stepper applies each body's impulse at its own point.
  Vec3 p_G = Vec3::Zero();
  Vec3 n_G = Vec3::UnitY();  ///< unit normal from body1 towards body2, in G
  double depth = 0.0;        ///< overlap (m); negative: gap
  double friction = 0.0;     ///< Coulomb coefficient mu >= 0 (|tangential| <= mu normal)
  double restitution = 0.0;  ///< Newton's coefficient e in [0, 1] on the normal approach speed
};

/// What a contact method asks of collision detection: the contacts of a state. Called once per
/// step at the step's start (positions and velocities of `state`). Must be callable from one
/// thread at a time per provider object; `contacts` arrives empty and is filled (its capacity
/// is kept by the caller, so a provider that only push_backs allocates nothing once warm).
class ContactProvider {
 public:
  virtual ~ContactProvider() = default;
  virtual void FindContacts(const System& system, const State& state,
                            std::vector<UnilateralContact>& contacts) const = 0;
};

}  // namespace sinew::engine
