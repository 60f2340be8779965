// libFuzzer target: any byte string given to the .sto/.mot reader either loads or throws
// sinew::Error; anything else (a crash, another exception, a sanitizer report, a hang) is a bug.
// A table that loads is also written back and read again, which must succeed.
#include <sinew/common/error.h>
#include <sinew/io/storage.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  sinew::io::Storage storage;
  try {
    storage = sinew::io::ParseStorage(text, "fuzz.sto");
  } catch (const sinew::Error&) {
    return 0;  // rejected with a message: fine
  }
  // Whatever was accepted has a consistent shape and survives a write/read round trip.
  if (storage.values.size() != storage.time.size() * storage.labels.size()) __builtin_trap();
  const sinew::io::Storage again =
      sinew::io::ParseStorage(sinew::io::FormatStorage(storage), "fuzz-again.sto");
  if (again.NumRows() != storage.NumRows() || again.NumColumns() != storage.NumColumns()) {
    __builtin_trap();
  }
  return 0;
}
