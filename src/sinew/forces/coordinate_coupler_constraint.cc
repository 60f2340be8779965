#include <sinew/common/error.h>
#include <sinew/engine/state.h>
#include <sinew/forces/coordinate_coupler_constraint.h>

#include <algorithm>
#include <array>
#include <utility>

namespace sinew::forces {

CoordinateCouplerConstraint::CoordinateCouplerConstraint(std::string name,
                                                         std::vector<int> independent,
                                                         int dependent, functions::FunctionPtr f,
                                                         double scale_factor)
    : name_(std::move(name)),
      independent_(std::move(independent)),
      dependent_(dependent),
      f_(std::move(f)),
      scale_(scale_factor) {
  if (!f_) throw Error(SourceLocation{}, name_, "has no coupled_coordinates_function");
  if (independent_.empty()) throw Error(SourceLocation{}, name_, "has no independent coordinate");
  if (f_->NumArguments() != static_cast<int>(independent_.size())) {
    throw Error(SourceLocation{}, name_,
                "coupled_coordinates_function (" + f_->TypeName() + ") takes " +
                    std::to_string(f_->NumArguments()) + " argument(s) but " +
                    std::to_string(independent_.size()) + " independent coordinate(s) are named");
  }
  std::vector<int> all = Coordinates();
  std::sort(all.begin(), all.end());
  if (std::adjacent_find(all.begin(), all.end()) != all.end()) {
    throw Error(SourceLocation{}, name_, "names one coordinate twice");
  }
}

std::vector<int> CoordinateCouplerConstraint::Coordinates() const {
  std::vector<int> c = independent_;
  c.push_back(dependent_);
  return c;
}

std::vector<double> CoordinateCouplerConstraint::IndependentValues(
    const engine::State& state) const {
  std::vector<double> x(independent_.size());
  for (size_t i = 0; i < independent_.size(); ++i) x[i] = state.q[independent_[i]];
  return x;
}

void CoordinateCouplerConstraint::CalcPositionError(const engine::System&,
                                                    const engine::State& state,
                                                    Eigen::Ref<VecX> phi) const {
  phi[0] = state.q[dependent_] - scale_ * f_->CalcN(IndependentValues(state));
}

void CoordinateCouplerConstraint::CalcJacobian(const engine::System&, const engine::State& state,
                                               Eigen::Ref<MatX> J) const {
  const std::vector<double> x = IndependentValues(state);
  const int n = static_cast<int>(independent_.size());
  for (int i = 0; i < n; ++i) {
    const std::array<int, 1> wrt = {i};
    J(0, i) = -scale_ * f_->CalcPartialN(x, wrt);
  }
  J(0, n) = 1.0;
}

void CoordinateCouplerConstraint::CalcAccelerationRhs(const engine::System&,
                                                      const engine::State& state,
                                                      Eigen::Ref<VecX> b) const {
  // d/dt (J u) = J udot + Jdot u with Jdot u = -s sum_ij f_ij qdot_j u_i and qdot = u.
  const std::vector<double> x = IndependentValues(state);
  const int n = static_cast<int>(independent_.size());
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const std::array<int, 2> wrt = {i, j};
      sum += f_->CalcPartialN(x, wrt) * state.u[independent_[i]] * state.u[independent_[j]];
    }
  }
  b[0] = scale_ * sum;
}

}  // namespace sinew::forces
