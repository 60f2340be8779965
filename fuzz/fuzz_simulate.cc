// libFuzzer target for the whole path of `sinew simulate`: .osim text -> reader -> OpenSimParser
// (skeleton, actuators, excitations) -> engine::System -> default state -> a short simulation.
// Every stage either succeeds or throws sinew::Error; anything else (a crash, another exception,
// a sanitizer report, a hang) is a bug. Input is split: the first byte picks the integrator and
// whether actuators are excited, the rest is the model.
//
// The simulation is kept short so that one input costs milliseconds: 5 fixed steps of 1 ms with
// "euler", or rk45 up to 5 ms with its step bounded to 1 ms and a loose accuracy (its step-size
// floor of 1e-6 s bounds the number of rejections).
#include <sinew/common/error.h>
#include <sinew/engine/assemble.h>
#include <sinew/engine/integrator.h>
#include <sinew/engine/system.h>
#include <sinew/io/osim_reader.h>
#include <sinew/opensim/parser.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const bool rk45 = (data[0] & 1) != 0;
  const bool activate = (data[0] & 2) != 0;
  try {
    sinew::model::ModelSpec spec = sinew::io::ReadOsimString(
        std::string(reinterpret_cast<const char*>(data) + 1, size - 1), "fuzz.osim");
    sinew::opensim::OpenSimParser parser;
    parser.ActivateActuators(activate);
    auto system = std::make_unique<sinew::engine::System>();
    parser.ParseSpec(*system, std::move(spec));
    system->Finalize();
    sinew::engine::State state = sinew::engine::MakeDefaultState(*system);
    sinew::engine::IntegratorSettings settings;
    settings.step = 1e-3;
    settings.accuracy = 1e-3;
    settings.min_step = 1e-6;
    const auto integrator =
        sinew::engine::MakeIntegrator(rk45 ? "rk45" : "euler", *system, settings);
    integrator->SetController(parser.GetController());
    integrator->StepTo(state, 5e-3);
  } catch (const sinew::Error&) {
    // Rejected with a message: fine.
  }
  return 0;
}
