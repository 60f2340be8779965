// libFuzzer target: any byte string given to the ControlSet reader (`*_controls.xml`) either
// loads or throws sinew::Error; anything else (a crash, another exception, a sanitizer report, a
// hang) is a bug. Every control that loads is evaluated (value and derivatives) before, inside
// and after its nodes, as a simulation would.
#include <sinew/common/error.h>
#include <sinew/io/read_controls.h>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto controls = sinew::io::ParseControlSet(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz_controls.xml");
    for (const auto& [actuator, function] : controls) {
      for (double t : {-1.0, 0.0, 0.25, 0.5, 1.0, 1e6}) {
        volatile double sink =
            function->Calc(t) + function->CalcDerivative(t, 1) + function->CalcDerivative(t, 2);
        (void)sink;
      }
    }
  } catch (const sinew::Error&) {
    // Rejected with a message: fine.
  }
  return 0;
}
