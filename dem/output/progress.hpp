// Progress on the terminal: simulated time, realtime factor, ETA and the current
// load. On a terminal one line is redrawn in place; otherwise (a log file, CI)
// plain lines are printed every 10 % of the run.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace icedem {

/// One progress line: on a terminal redrawn in place at most 5 times a second, otherwise
/// (a log file, CI) printed as a new line at every 10 % of the work.
class ProgressLine {
 public:
  explicit ProgressLine(std::FILE* out);
  /// Whether a line for `fraction` (0..1) done is due now.
  bool due(double fraction) const;
  /// Print `line` for `fraction` done (call when due).
  void show(const std::string& line, double fraction);
  /// Finish the line (terminal mode): always, or only if one was drawn.
  void done(bool only_if_drawn);

 private:
  using Clock = std::chrono::steady_clock;
  bool tty_;
  std::FILE* out_;
  Clock::time_point last_print_;
  int next_decile_ = 1;
  bool drawn_ = false;
};

class Progress {
 public:
  /// `duration`: simulated time of the run, s. `enabled`: print anything at all.
  Progress(double duration, bool enabled, std::FILE* out = stderr);

  /// Report the state after a step: simulated time (s), surge load (N), awake floes.
  void update(double sim_time, double surge_load, int awake);

  /// Finish the line (terminal mode).
  void done();

 private:
  double duration_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  ProgressLine line_;
};

/// Progress of the set-up before the first step (the layout's relaxation): nothing for a
/// set-up shorter than a few seconds, then the stage and its share done, on a ProgressLine.
class SetupProgress {
 public:
  explicit SetupProgress(bool enabled, std::FILE* out = stderr);
  /// `fraction` (0..1) of `stage` done.
  void update(const char* stage, double fraction);
  /// Finish the line (terminal mode), if one was drawn.
  void done();

 private:
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  ProgressLine line_;
};

}  // namespace icedem
