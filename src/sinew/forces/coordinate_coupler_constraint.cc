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

namespace {

// The independent coordinates' values, on the stack for up to kInline of them: a coupler is
// evaluated several times per step and must not use the heap there (EvaluationAllocationTest).
class IndependentValues {
 public:
  IndependentValues(const std::vector<int>& coordinates, const VecX& q) : n_(coordinates.size()) {
    if (n_ > kInline) heap_.resize(n_);
    double* x = n_ > kInline ? heap_.data() : inline_.data();
    for (size_t i = 0; i < n_; ++i) x[i] = q[coordinates[i]];
  }
  std::span<const double> values() const {
    return {n_ > kInline ? heap_.data() : inline_.data(), n_};
  }

 private:
  static constexpr size_t kInline = 8;
  size_t n_;
  std::array<double, kInline> inline_{};
  std::vector<double> heap_;
};

}  // namespace

void CoordinateCouplerConstraint::CalcPositionError(const engine::System&,
                                                    const engine::State& state,
                                                    Eigen::Ref<VecX> phi) const {
  phi[0] =
      state.q[dependent_] - scale_ * f_->CalcN(IndependentValues(independent_, state.q).values());
}

void CoordinateCouplerConstraint::CalcJacobian(const engine::System&, const engine::State& state,
                                               Eigen::Ref<MatX> J) const {
  const IndependentValues x(independent_, state.q);
  const int n = static_cast<int>(independent_.size());
  for (int i = 0; i < n; ++i) {
    const std::array<int, 1> wrt = {i};
    J(0, i) = -scale_ * f_->CalcPartialN(x.values(), wrt);
  }
  J(0, n) = 1.0;
}

void CoordinateCouplerConstraint::CalcAccelerationRhs(const engine::System&,
                                                      const engine::State& state,
                                                      Eigen::Ref<VecX> b) const {
  // d/dt (J u) = J udot + Jdot u with Jdot u = -s sum_ij f_ij qdot_j u_i and qdot = u.
  const IndependentValues x(independent_, state.q);
  const int n = static_cast<int>(independent_.size());
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const std::array<int, 2> wrt = {i, j};
      sum +=
          f_->CalcPartialN(x.values(), wrt) * state.u[independent_[i]] * state.u[independent_[j]];
    }
  }
  b[0] = scale_ * sum;
}

std::vector<std::pair<int, double>> CoordinateCouplerConstraint::Breakpoints() const {
  std::vector<std::pair<int, double>> points;
  if (independent_.size() != 1) return points;
  for (const double x : f_->Breakpoints()) points.emplace_back(independent_[0], x);
  return points;
}

}  // namespace sinew::forces
