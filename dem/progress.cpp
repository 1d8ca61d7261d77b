#include "dem/progress.hpp"

#include <unistd.h>

#include <fmt/format.h>

namespace icedem {
namespace {
std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  return fmt::format("{}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
}
}  // namespace

Progress::Progress(double duration, bool enabled, std::FILE* out)
    : duration_(duration), enabled_(enabled), tty_(isatty(fileno(out)) != 0), out_(out),
      start_(Clock::now()), last_print_(start_) {}

void Progress::update(double sim_time, double surge_load, int awake) {
  if (!enabled_) return;
  const Clock::time_point now = Clock::now();
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double fraction = sim_time / duration_;
  if (tty_) {
    // redraw at most 5 times a second
    if (std::chrono::duration<double>(now - last_print_).count() < 0.2 && fraction < 1.0) return;
  } else if (fraction * 10 < next_decile_) {
    return;
  }
  last_print_ = now;
  const double rtf = wall > 0 ? sim_time / wall : 0.0;
  const double eta = rtf > 0 ? (duration_ - sim_time) / rtf : 0.0;
  const std::string line =
      fmt::format("t = {:7.1f} / {:.0f} s  {:5.1f}x real time  ETA {}  surge load {:7.2f} N  awake {}",
                  sim_time, duration_, rtf, clock_text(eta), surge_load, awake);
  if (tty_) {
    fmt::print(out_, "\r{}\033[K", line);
  } else {
    fmt::print(out_, "{}\n", line);
    while (fraction * 10 >= next_decile_) ++next_decile_;
  }
  std::fflush(out_);
}

void Progress::done() {
  if (enabled_ && tty_) fmt::print(out_, "\n");
}

SetupProgress::SetupProgress(bool enabled, std::FILE* out)
    : enabled_(enabled), tty_(isatty(fileno(out)) != 0), out_(out), start_(Clock::now()), last_print_(start_) {}

void SetupProgress::update(const char* stage, double fraction) {
  // a set-up of a few seconds goes unannounced
  constexpr double kQuietSeconds = 3.0;
  if (!enabled_) return;
  const Clock::time_point now = Clock::now();
  const double wall = std::chrono::duration<double>(now - start_).count();
  if (wall < kQuietSeconds) return;
  if (tty_) {
    if (std::chrono::duration<double>(now - last_print_).count() < 0.2 && fraction < 1.0) return;
  } else if (fraction * 10 < next_decile_) {
    return;
  }
  last_print_ = now;
  const double eta = fraction > 0 ? wall * (1 - fraction) / fraction : 0.0;
  const std::string line = fmt::format("setting up: {} {:3.0f} %  ETA {}", stage, 100 * fraction, clock_text(eta));
  if (tty_) {
    fmt::print(out_, "\r{}\033[K", line);
  } else {
    fmt::print(out_, "{}\n", line);
    while (fraction * 10 >= next_decile_) ++next_decile_;
  }
  drawn_ = true;
  std::fflush(out_);
}

void SetupProgress::done() {
  if (enabled_ && tty_ && drawn_) fmt::print(out_, "\n");
}

}  // namespace icedem
