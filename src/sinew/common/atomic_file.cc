#include <fcntl.h>
#include <sinew/common/atomic_file.h>
#include <sinew/common/error.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace sinew {
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& what, int error) {
  throw Error(SourceLocation{path, 0}, "",
              "cannot write the file: " + what +
                  (error ? ": " + std::string(std::strerror(error)) : std::string()));
}

// Creates a new, empty temporary file beside `path` (O_EXCL: never an existing file or link)
// with the permissions an ordinary new file gets (0666 less the umask). Returns its name.
std::string CreateTemporary(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    // NAME.tmp.PID.N, with NAME cut to 200 bytes so that the suffix never makes a name longer
    // than the 255 bytes file systems allow when the destination's own name fits.
    const size_t slash = path.rfind('/');
    const size_t name_start = slash == std::string::npos ? 0 : slash + 1;
    const std::string name =
        path.substr(0, name_start + std::min<size_t>(path.size() - name_start, 200)) + ".tmp." +
        std::to_string(getpid()) + "." + std::to_string(counter++);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return name;
    }
    if (errno != EEXIST) Fail(path, "cannot create a temporary file beside it", errno);
  }
  Fail(path, "cannot find a free temporary file name beside it", 0);
}

// Flushes the file's data to the disk, so that a crash after the rename cannot leave an empty
// or partial file under the final name.
void Sync(const std::string& temporary, const std::string& path) {
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) Fail(path, "cannot reopen the temporary file", errno);
  const bool synced = ::fsync(fd) == 0;
  const int error = errno;
  if (::close(fd) != 0 || !synced) Fail(path, "cannot sync the temporary file", error);
}

}  // namespace

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  if (path.empty()) throw Error("cannot write a file with an empty name");
  temporary_ = CreateTemporary(path);
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temporary_.c_str());
}

void AtomicFile::Commit() {
  try {
    Sync(temporary_, path_);
    if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
      Fail(path_, "cannot rename the temporary file to it", errno);
    }
    committed_ = true;
  } catch (...) {
    std::remove(temporary_.c_str());
    committed_ = true;  // nothing left to remove
    throw;
  }
}

void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  AtomicFile file(path);
  std::ofstream out(file.temporary(), std::ios::binary | std::ios::trunc);
  if (!out) Fail(path, "cannot open the temporary file " + file.temporary(), errno);
  write(out);
  out.flush();
  if (!out) Fail(path, "the data could not all be written (disk full?)", errno);
  out.close();
  if (out.fail()) Fail(path, "the data could not all be written (disk full?)", errno);
  file.Commit();
}

void WriteFileAtomically(const std::string& path, std::string_view bytes) {
  WriteFileAtomically(path, [bytes](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace sinew
