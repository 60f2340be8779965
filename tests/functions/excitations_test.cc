#include <gtest/gtest.h>
#include <sinew/common/error.h>
#include <sinew/functions/excitations.h>
#include <sinew/functions/functions.h>

#include <cmath>
#include <numbers>

namespace sinew {
namespace {

TEST(ExcitationsTest, RampIsZeroBeforeStartThenLinear) {
  functions::Ramp ramp(0.5, 2.0);
  EXPECT_EQ(ramp.Calc(0.0), 0.0);
  EXPECT_EQ(ramp.Calc(0.5), 0.0);
  EXPECT_EQ(ramp.Calc(0.75), 0.5);
  EXPECT_EQ(ramp.CalcDerivative(0.25, 1), 0.0);
  EXPECT_EQ(ramp.CalcDerivative(0.5, 1), 2.0);  // right derivative at the kink
  EXPECT_EQ(ramp.CalcDerivative(1.0, 2), 0.0);
}

TEST(ExcitationsTest, SineExcitationUsesHertz) {
  functions::SineExcitation u(0.5, 2.0, 0.25, 0.5);
  const double omega = 4.0 * std::numbers::pi;
  EXPECT_DOUBLE_EQ(u.Calc(0.1), 0.5 * std::sin(omega * 0.1 + 0.25) + 0.5);
  EXPECT_DOUBLE_EQ(u.CalcDerivative(0.1, 1), 0.5 * omega * std::cos(omega * 0.1 + 0.25));
  EXPECT_DOUBLE_EQ(u.CalcDerivative(0.1, 2), -0.5 * omega * omega * std::sin(omega * 0.1 + 0.25));
  // One full period after t the value repeats.
  EXPECT_NEAR(u.Calc(0.1 + 0.5), u.Calc(0.1), 1e-15);
}

TEST(ExcitationsTest, CallableFunctionDifferentiatesNumerically) {
  functions::CallableFunction f([](double x) { return std::exp(0.5 * x) * std::sin(x); });
  for (double x : {-2.0, 0.0, 0.7, 5.0}) {
    const double e = std::exp(0.5 * x);
    const double d1 = e * (0.5 * std::sin(x) + std::cos(x));
    const double d2 = e * (-0.75 * std::sin(x) + std::cos(x));
    EXPECT_EQ(f.Calc(x), e * std::sin(x));
    // Documented accuracy: about 1e-10 and 1e-7 relative for unit-scale smooth functions.
    EXPECT_NEAR(f.CalcDerivative(x, 1), d1, 1e-9 * std::max(1.0, e));
    EXPECT_NEAR(f.CalcDerivative(x, 2), d2, 1e-6 * std::max(1.0, e));
  }
  EXPECT_THROW(functions::CallableFunction(nullptr), Error);
}

TEST(ExcitationsTest, OpenSimTypesAreBuiltFromCpp) {
  functions::FunctionPtr u = std::make_shared<functions::SimmSpline>(
      std::vector<double>{0.0, 0.5, 1.0}, std::vector<double>{0.0, 1.0, 0.0});
  EXPECT_DOUBLE_EQ(u->Calc(0.5), 1.0);
}

}  // namespace
}  // namespace sinew
