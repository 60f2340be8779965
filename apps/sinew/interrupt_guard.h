// InterruptGuard: while it lives, SIGINT and SIGTERM set a flag instead of killing the program,
// so a long command can stop cleanly and keep its work. A second signal of the same kind
// kills as usual (the handler resets itself).
#pragma once

#include <atomic>
#include <string>

namespace sinew::cli {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// True once SIGINT or SIGTERM arrived.
  const std::atomic<bool>& flag() const;
  /// The signal that arrived (0 for none), and its name ("SIGINT", "SIGTERM").
  int Signal() const;
  std::string SignalName() const;
};

/// Thrown by a command to end the program with `code` after it has reported why itself.
struct ExitRequest {
  int code;
};

}  // namespace sinew::cli
