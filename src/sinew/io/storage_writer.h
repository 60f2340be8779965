// StorageWriter: a storage file (.sto) written row by row as a simulation computes it, so that
// memory stays bounded whatever the duration. Rows go to a temporary file beside the target;
// Finish() writes the row count into the header and renames the file into place, so a reader
// never sees a half-written file under the final name (nor is a symlink at that name
// followed). An unfinished writer removes its temporary file.
#pragma once

#include <sinew/common/atomic_file.h>
#include <sinew/io/storage.h>

#include <cstdio>
#include <span>
#include <string>

namespace sinew::io {

/// Writes one storage file incrementally.
class StorageWriter {
 public:
  /// Opens a temporary file in `file`'s folder and writes the header of `header` (name,
  /// metadata, labels, in_degrees; its rows are ignored), with room for the row count and for
  /// a `status` line ("complete", or "partial: ..." when the run stopped early). Throws
  /// sinew::Error naming the file when it cannot be created.
  StorageWriter(const std::string& file, const Storage& header);
  ~StorageWriter();
  StorageWriter(const StorageWriter&) = delete;
  StorageWriter& operator=(const StorageWriter&) = delete;

  /// Appends a row of NumColumns() values at time `t`. Throws sinew::Error when the row has
  /// the wrong length or the disk refuses the write.
  void AppendRow(double t, std::span<const double> row);
  /// Rows written so far.
  long rows() const { return rows_; }

  /// Writes the row count and the status into the header, flushes, and moves the file to its
  /// name. `partial_reason` empty: status=complete; otherwise status=partial (the reason).
  /// Throws sinew::Error when the disk refuses (the temporary file is then removed).
  void Finish(const std::string& partial_reason = "");

 private:
  void Check(bool ok, const char* what);

  std::string file_;
  AtomicFile atomic_;  // the temporary beside file_, moved into place by Finish
  std::FILE* out_ = nullptr;
  size_t columns_ = 0;
  long rows_ = 0;
  long count_offset_ = 0;   // where the row count's field starts
  long status_offset_ = 0;  // where the status field starts
  std::string line_;        // reused row buffer
};

}  // namespace sinew::io
