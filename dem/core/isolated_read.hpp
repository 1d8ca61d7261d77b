// Reading a file that may be damaged, in a child process.
//
// HDF5 1.10 (Debian 12) does not always report damaged metadata as an error: a bit flipped in a
// group's symbol table can send it into unbounded recursion (a stack overflow) or past the end of
// a buffer (a segmentation fault). A file a command did not write itself (a checkpoint to resume,
// an output to describe) is therefore first read in a forked child: if that reader crashes or
// hangs, the command refuses the file as damaged (exit 2) instead of crashing with it.
#pragma once

#include <functional>
#include <string>

namespace icedem {

/// What a reader run by read_isolated returned, or why it did not.
struct IsolatedResult {
  bool ok = false;
  std::string value;  // the reader's result if ok, else why not: its exception's message, or how it died
};

/// Runs `reader` in a forked child and returns the string it returns. The child is killed after
/// `timeout_s`. An exception the reader throws comes back as its message (ok false); a crash or a
/// timeout as a sentence saying so.
IsolatedResult read_isolated(const std::function<std::string()>& reader, double timeout_s);

}  // namespace icedem
