// Progress on the terminal: simulated time, realtime factor, ETA and the current
// load. On a terminal one line is redrawn in place; otherwise (a log file, CI)
// plain lines are printed every 10 % of the run.
#pragma once

#include <chrono>
#include <cstdio>

namespace icedem {

class Progress {
 public:
  /// `duration`: simulated time of the run, s. `enabled`: print anything at all.
  Progress(double duration, bool enabled, std::FILE* out = stderr);

  /// Report the state after a step: simulated time (s), surge load (N), awake floes.
  void update(double sim_time, double surge_load, int awake);

  /// Finish the line (terminal mode).
  void done();

 private:
  using Clock = std::chrono::steady_clock;
  double duration_;
  bool enabled_;
  bool tty_;
  std::FILE* out_;
  Clock::time_point start_;
  Clock::time_point last_print_;
  int next_decile_ = 1;
};

/// Progress of the set-up before the first step (the layout's relaxation): nothing for a
/// set-up shorter than a few seconds, then the stage and its share done, redrawn on a
/// terminal, a line every 10 % otherwise.
class SetupProgress {
 public:
  explicit SetupProgress(bool enabled, std::FILE* out = stderr);
  /// `fraction` (0..1) of `stage` done.
  void update(const char* stage, double fraction);
  /// Finish the line (terminal mode), if one was drawn.
  void done();

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  bool tty_;
  std::FILE* out_;
  Clock::time_point start_;
  Clock::time_point last_print_;
  int next_decile_ = 1;
  bool drawn_ = false;
};

}  // namespace icedem
