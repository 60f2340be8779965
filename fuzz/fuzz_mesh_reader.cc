// libFuzzer target for the mesh readers. The first byte picks the format (its value modulo 3:
// 0 .vtp, 1 .obj, 2 .stl) and the rest is the file. A mesh either loads or the reader throws
// sinew::Error; anything else (a crash, another exception, a sanitizer report, a hang, an
// allocation beyond -rss_limit_mb) is a bug. A mesh that loads must be valid (indices in range,
// one normal per vertex).
#include <sinew/common/error.h>
#include <sinew/io/mesh_obj.h>
#include <sinew/io/mesh_stl.h>
#include <sinew/io/mesh_vtp.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    sinew::io::TriangleMesh mesh;
    switch (data[0] % 3) {
      case 0:
        mesh = sinew::io::ParseVtp(std::string(bytes), "fuzz.vtp");
        break;
      case 1:
        mesh = sinew::io::ParseObj(bytes, "fuzz.obj");
        break;
      default:
        mesh = sinew::io::ParseStl(bytes, "fuzz.stl");
        break;
    }
    // Throws sinew::Error for a mesh the reader should have rejected: that escapes as a bug.
    try {
      sinew::io::ValidateMesh(mesh, "fuzz");
    } catch (const sinew::Error&) {
      __builtin_trap();
    }
  } catch (const sinew::Error&) {
    // Rejected with a message: fine.
  }
  return 0;
}
