#include <sinew/common/error.h>
#include <sinew/io/internal/number_text.h>
#include <sinew/io/storage_writer.h>

#include <cerrno>
#include <cstring>

namespace sinew::io {
namespace {

constexpr int kCountWidth = 20;   // digits of the row count field (enough for any long)
constexpr int kStatusWidth = 96;  // characters of the status field

std::string Padded(std::string text, size_t width) {
  if (text.size() > width) text.resize(width);
  text.append(width - text.size(), ' ');
  return text;
}

}  // namespace

StorageWriter::StorageWriter(const std::string& file, const Storage& header)
    : file_(file), atomic_(file), columns_(header.labels.size()) {
  out_ = std::fopen(atomic_.temporary().c_str(), "wb");
  if (!out_) {
    throw Error(SourceLocation{file_, 0}, "",
                std::string("cannot create the file: ") + std::strerror(errno));
  }
  Storage empty = header;
  empty.time.clear();
  empty.values.clear();
  std::string text = FormatStorage(empty);
  // Make room for the final row count and a status line (fixed width, patched by Finish).
  const std::string count_line = "\nnRows=0\n";
  const size_t count = text.find(count_line);
  if (count == std::string::npos) throw Error("StorageWriter: unexpected header layout");
  count_offset_ = static_cast<long>(count + 7);
  text.replace(count + 7, 1, std::string(kCountWidth, ' '));
  const size_t end = text.find("endheader\n");
  status_offset_ = static_cast<long>(end + 7);
  text.insert(end, "status=" + Padded("running", kStatusWidth) + "\n");
  Check(std::fwrite(text.data(), 1, text.size(), out_) == text.size(), "write the header");
}

StorageWriter::~StorageWriter() {
  if (out_) std::fclose(out_);  // the AtomicFile removes the unfinished temporary
}

void StorageWriter::Check(bool ok, const char* what) {
  if (ok) return;
  const std::string reason = std::strerror(errno);
  if (out_) std::fclose(out_);
  out_ = nullptr;
  throw Error(SourceLocation{file_, 0}, "",
              std::string("cannot ") + what + ": " + reason + " (nothing was written)");
}

void StorageWriter::AppendRow(double t, std::span<const double> row) {
  if (!out_) throw Error(SourceLocation{file_, 0}, "", "the file is already closed");
  if (row.size() != columns_) {
    throw Error(SourceLocation{file_, 0}, "",
                "a row of " + std::to_string(row.size()) + " values for " +
                    std::to_string(columns_) + " columns");
  }
  line_.clear();
  internal::AppendNumber(line_, t);
  for (double v : row) {
    line_ += '\t';
    internal::AppendNumber(line_, v);
  }
  line_ += '\n';
  Check(std::fwrite(line_.data(), 1, line_.size(), out_) == line_.size(), "write a row");
  ++rows_;
}

void StorageWriter::Finish(const std::string& partial_reason) {
  if (!out_) throw Error(SourceLocation{file_, 0}, "", "the file is already closed");
  const std::string count = Padded(std::to_string(rows_), kCountWidth);
  const std::string status = Padded(
      partial_reason.empty() ? "complete" : "partial (" + partial_reason + ")", kStatusWidth);
  Check(std::fseek(out_, count_offset_, SEEK_SET) == 0 &&
            std::fwrite(count.data(), 1, count.size(), out_) == count.size() &&
            std::fseek(out_, status_offset_, SEEK_SET) == 0 &&
            std::fwrite(status.data(), 1, status.size(), out_) == status.size(),
        "write the header");
  Check(std::fflush(out_) == 0, "flush the file");
  const int closed = std::fclose(out_);
  out_ = nullptr;
  if (closed != 0) {
    throw Error(SourceLocation{file_, 0}, "", "cannot close the file (nothing was written)");
  }
  atomic_.Commit();
}

}  // namespace sinew::io
