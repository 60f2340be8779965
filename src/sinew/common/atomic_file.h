// Writing an output file so that it is either complete or absent: the bytes go to a temporary
// file in the same folder, which is checked, synced and then renamed over the destination.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <string_view>

namespace sinew {

/// Writes `path` through `write`, which fills the stream it is given. The stream is a new file
/// `<path>.tmp.<pid>.<n>` in the same folder (the name part cut to 200 bytes); after `write`
/// returns, the stream is flushed, closed and synced, and every step is checked (a full disk is an
/// error, not a short file). Only then is the temporary renamed to `path`: a reader sees the old
/// file or the whole new one, never a part. An existing `path` that is a symbolic link is replaced
/// by the new file, not followed, so a link cannot make Sinew overwrite a file elsewhere. On any
/// failure (including an exception from `write`, which is rethrown) the temporary is removed and
/// `path` is left as it was. Throws sinew::Error naming `path` when the file cannot be written.
void WriteFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

/// The mechanism under WriteFileAtomically, for files written piece by piece (a simulation's
/// streamed tables): a new temporary file beside `path` (never an existing file or link),
/// synced and renamed to `path` by Commit(), removed if the AtomicFile is destroyed first.
class AtomicFile {
 public:
  /// Creates the temporary. Throws sinew::Error naming `path` when it cannot.
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }
  /// The temporary file's name, to open and write (it exists, empty).
  const std::string& temporary() const { return temporary_; }
  /// Syncs the temporary (its writer must have closed it) and renames it to path(). Throws
  /// sinew::Error naming path() on failure (the temporary is then removed).
  void Commit();

 private:
  std::string path_, temporary_;
  bool committed_ = false;
};

/// WriteFileAtomically with the whole content at hand.
void WriteFileAtomically(const std::string& path, std::string_view bytes);

}  // namespace sinew
