// One writer per output file: a run holds an exclusive lock (flock) on its
// HDF5 file for as long as it runs, so that a second run given the same -o is
// refused instead of mixing its results into the first one's file. The lock is
// taken before the file is truncated, and released when the process ends. While it is held,
// a Ctrl-C or SIGTERM before the run takes them over (set-up can take long; the run takes them
// just before it writes the file's layout, dem/run/simulation.cpp) ends the process with a
// message and exit code 128 + the signal, removing the file if the lock created it and nothing
// was written to it. Its handlers are in place before it creates the file.
#pragma once

#include <csignal>
#include <string>

namespace icedem {

class OutputLock {
 public:
  /// Lock `path` (creating it empty if it does not exist). Throws InputError
  /// naming the file if another process holds it.
  explicit OutputLock(const std::string& path);
  /// Releases the lock; removes the file if this lock created it and it is still
  /// empty (the run stopped before writing anything).
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
  bool created_ = false;
  void (*previous_int_)(int) = SIG_DFL;   // the signal handlers before the lock
  void (*previous_term_)(int) = SIG_DFL;
};

}  // namespace icedem
