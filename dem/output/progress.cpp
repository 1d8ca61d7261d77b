#include "dem/output/progress.hpp"

#include <unistd.h>

#include <fmt/format.h>

namespace icedem {
namespace {
std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  return fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
}  // namespace

ProgressLine::ProgressLine(std::FILE* out)
    : tty_(isatty(fileno(out)) != 0), out_(out), last_print_(Clock::now()) {}

bool ProgressLine::due(double fraction) const {
  // a terminal: redraw at most 5 times a second (and at the end); a file: every 10 %
  return tty_ ? seconds_since(last_print_) >= 0.2 || fraction >= 1.0 : fraction * 10 >= next_decile_;
}

void ProgressLine::show(const std::string& line, double fraction) {
  last_print_ = Clock::now();
  if (tty_) {
    fmt::print(out_, "\r{}\033[K", line);
  } else {
    fmt::print(out_, "{}\n", line);
    while (fraction * 10 >= next_decile_) ++next_decile_;
  }
  drawn_ = true;
  std::fflush(out_);
}

void ProgressLine::done(bool only_if_drawn) {
  if (tty_ && (drawn_ || !only_if_drawn)) fmt::print(out_, "\n");
}

Progress::Progress(double duration, bool enabled, std::FILE* out)
    : duration_(duration), enabled_(enabled), start_(std::chrono::steady_clock::now()), line_(out) {}

void Progress::update(double sim_time, double surge_load, int awake) {
  if (!enabled_) return;
  const double fraction = sim_time / duration_;
  if (!line_.due(fraction)) return;
  const double wall = seconds_since(start_);
  const double rtf = wall > 0 ? sim_time / wall : 0.0;
  const double eta = rtf > 0 ? (duration_ - sim_time) / rtf : 0.0;
  line_.show(fmt::format("t = {:7.1f} / {:.0f} s  {:5.1f}x real time  ETA {}  surge load {:7.2f} N  awake {}",
                         sim_time, duration_, rtf, clock_text(eta), surge_load, awake),
             fraction);
}

void Progress::done() {
  if (enabled_) line_.done(false);
}

SetupProgress::SetupProgress(bool enabled, std::FILE* out)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()), line_(out) {}

void SetupProgress::update(const char* stage, double fraction) {
  // a set-up of a few seconds goes unannounced
  constexpr double kQuietSeconds = 3.0;
  if (!enabled_) return;
  const double wall = seconds_since(start_);
  if (wall < kQuietSeconds || !line_.due(fraction)) return;
  const double eta = fraction > 0 ? wall * (1 - fraction) / fraction : 0.0;
  line_.show(fmt::format("setting up: {} {:3.0f} %  ETA {}", stage, 100 * fraction, clock_text(eta)), fraction);
}

void SetupProgress::done() {
  if (enabled_) line_.done(true);  // a set-up too short to announce leaves no blank line
}

}  // namespace icedem
