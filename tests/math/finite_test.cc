// AllFinite against Eigen's allFinite: every position of an infinity or a NaN, and the largest
// finite values (whose plain sum would overflow, which AllFinite must not take for infinite).
#include <gtest/gtest.h>
#include <sinew/math/finite.h>
#include <sinew/math/types.h>

#include <limits>

namespace sinew {
namespace {

TEST(AllFiniteTest, AgreesWithEigensAllFiniteForEveryBadEntryAndHugeValues) {
  const double bad[] = {std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::quiet_NaN()};
  for (int n : {1, 2, 3, 7, 16, 33}) {
    VecX x = VecX::LinSpaced(n, -5.0, 7.0);
    EXPECT_TRUE(AllFinite(x));
    for (int i = 0; i < n; ++i) {
      for (double value : bad) {
        VecX y = x;
        y[i] = value;
        EXPECT_FALSE(AllFinite(y)) << "n " << n << " at " << i << ": " << value;
        EXPECT_EQ(AllFinite(y), y.allFinite());
      }
    }
    // The largest finite values: their sum overflows, x - x does not.
    VecX huge = VecX::Constant(n, std::numeric_limits<double>::max());
    EXPECT_TRUE(AllFinite(huge));
    EXPECT_TRUE(AllFinite(VecX(-huge)));
  }
  EXPECT_TRUE(AllFinite(VecX()));  // nothing to be infinite
  const Mat3 m = Mat3::Identity();
  EXPECT_TRUE(AllFinite(m));
}

}  // namespace
}  // namespace sinew
