// libFuzzer target: any byte string given to the .osim reader either loads or throws
// sinew::Error; anything else (a crash, another exception, a sanitizer report, a hang) is a bug.
#include <sinew/io/osim_reader.h>

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    sinew::model::ModelSpec spec = sinew::io::ReadOsimString(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.osim");
    (void)spec;
  } catch (const sinew::Error&) {
    // Rejected with a message: fine.
  }
  return 0;
}
