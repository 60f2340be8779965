// The contacts table of a simulation (`sinew simulate --out DIR` writes DIR/contacts.sto when
// the model has contact forces): per contact force, the force and torque on each of its bodies
// and the number of contacts that act.
#pragma once

#include <sinew/engine/state.h>
#include <sinew/engine/system.h>

#include <string>
#include <vector>

namespace sinew::contact {

/// For every contact force of `system` (a contact::ContactForce, in element order): its
/// record groups' "<force>.<group>.force.X|Y|Z" and "<force>.<group>.torque.X|Y|Z" (the net
/// force, N, and the torque about the body's origin, N m, on that body, in G: forces.sto's
/// columns), then "<force>.active_contacts" and, for a force with pair groups (SMC), per body
/// pair "<force>.<body1>-<body2>.active_contacts". Empty when the system has no contact force.
std::vector<std::string> ContactTableLabels(const engine::System& system);

/// The values in ContactTableLabels order at `state` (`row` is resized).
void ContactTableRow(const engine::System& system, const engine::State& state,
                     std::vector<double>& row);

}  // namespace sinew::contact
