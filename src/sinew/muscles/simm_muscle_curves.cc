#include <sinew/functions/simm_spline.h>
#include <sinew/muscles/simm_muscle_curves.h>

#include <memory>
#include <vector>

namespace sinew::muscles {

functions::FunctionPtr MakeDefaultActiveForceLengthCurve() {
  return std::make_shared<functions::SimmSpline>(
      std::vector<double>{-5.307692, -4.307692, -1.923077, -0.884615, -0.269231, 0.230769,
                          0.461538,  0.52725,   0.62875,   0.71875,   0.86125,   1.045,
                          1.2175,    1.43875,   1.5,       1.615385,  2.0,       2.961538,
                          3.692308,  5.461538,  9.901902},
      std::vector<double>{0.012188, 0.021899, 0.036466, 0.052493, 0.075312, 0.114158, 0.157859,
                          0.226667, 0.636667, 0.856667, 0.95,     0.993333, 0.77,     0.246667,
                          0.193821, 0.133252, 0.072683, 0.044417, 0.036341, 0.021899, 0.007332});
}

functions::FunctionPtr MakeDefaultPassiveForceLengthCurve() {
  return std::make_shared<functions::SimmSpline>(
      std::vector<double>{-5.0, 0.998, 0.999, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.601, 1.602, 5.0},
      std::vector<double>{0.0, 0.0, 0.0, 0.0, 0.035, 0.12, 0.26, 0.55, 1.17, 2.0, 2.0, 2.0, 2.0});
}

functions::FunctionPtr MakeDefaultTendonForceLengthCurve() {
  return std::make_shared<functions::SimmSpline>(
      std::vector<double>{-10.0, -0.002, -0.001, 0.0, 0.00131, 0.00281, 0.00431, 0.00581, 0.00731,
                          0.00881, 0.0103, 0.0118, 0.0123, 9.2, 9.201, 9.202, 20.0},
      std::vector<double>{0.0, 0.0, 0.0, 0.0, 0.0108, 0.0257, 0.0435, 0.0652, 0.0915, 0.123, 0.161,
                          0.208, 0.227, 345.0, 345.0, 345.0, 345.0});
}

functions::FunctionPtr MakeDefaultForceVelocityCurve() {
  std::vector<double> x{-1.001};
  for (int k = -20; k <= 20; ++k) x.push_back(k / 20.0);  // -1, -0.95, ..., 1 (as written)
  return std::make_shared<functions::SimmSpline>(
      std::move(x),
      std::vector<double>{0.0,      0.0,      0.010417, 0.021739, 0.034091, 0.047619, 0.0625,
                          0.078947, 0.097222, 0.117647, 0.140625, 0.166667, 0.196429, 0.230769,
                          0.270833, 0.318182, 0.375,    0.444444, 0.53125,  0.642857, 0.791667,
                          1.0,      1.482014, 1.601571, 1.655791, 1.686739, 1.706751, 1.720753,
                          1.731099, 1.739055, 1.745365, 1.75049,  1.754736, 1.758312, 1.761364,
                          1.763999, 1.766298, 1.768321, 1.770115, 1.771717, 1.773155, 1.774455});
}

}  // namespace sinew::muscles
