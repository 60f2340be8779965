// OpenSim's ElasticFoundationForce (Simbody's ElasticFoundationForce): a bed of independent
// springs, one at the centroid of each triangle of a contact mesh, pressing against a
// half-space or a sphere. Only meshes carry springs (as in Simbody): a pair without a mesh
// makes no contact.
#pragma once

#include <sinew/contact/contact_force.h>
#include <sinew/contact/contact_shape.h>

#include <string>
#include <vector>

namespace sinew::contact {

/// For each triangle of a mesh whose centroid Q is inside the other shape: x the distance from
/// Q to the other shape's nearest surface point P, A the triangle's area, v_n the rate at
/// which the bodies approach at P: spring force f = k A x (1 + c v_n) from Q towards P on the
/// mesh (none when f <= 0), friction FrictionForce(f, v_slip, ...) of the mesh's material,
/// applied at P. Potential energy k A x^2 / 2 per spring.
class ElasticFoundationForce final : public ContactForce {
 public:
  /// `materials[i]` is used for mesh shapes only. Mesh/mesh pairs must not be given.
  ElasticFoundationForce(std::string name, std::vector<ContactShape> shapes,
                         std::vector<ContactMaterial> materials, double transition_velocity,
                         std::vector<RecordGroup> groups);

  double VisitContacts(const engine::State& state, ContactSink& sink) const override;

 private:
  /// One spring of a mesh: the triangle's centroid (in the shape's frame) and area.
  struct Spring {
    Vec3 p_CQ;
    double area;
  };
  std::vector<ContactShape> shapes_;
  std::vector<ContactMaterial> materials_;
  std::vector<std::vector<Spring>> springs_;  ///< per shape (empty unless a mesh)
  std::vector<std::pair<int, int>> pairs_;    ///< (mesh, other shape) on different bodies
  double transition_velocity_;
};

}  // namespace sinew::contact
