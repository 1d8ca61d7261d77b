#include "dem/output/lock.hpp"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "dem/core/errors.hpp"

namespace icedem {
namespace {

// Set-up (a layout read or generated, the world built) comes before the run loop and its
// clean stop at Ctrl-C: a signal then ends the process here, removing the output file the lock
// created if nothing was written to it yet (only async-signal-safe calls)
char g_path[4096];
volatile sig_atomic_t g_remove = 0;

extern "C" void on_signal_before_the_run(int signal) {
  struct stat st {};
  if (g_remove && ::stat(g_path, &st) == 0 && st.st_size == 0) {
    ::unlink(g_path);
    static const char msg[] = "\nicedem: interrupted before the run started; no output file written\n";
    [[maybe_unused]] const ssize_t n = ::write(2, msg, sizeof msg - 1);
  } else {
    static const char msg[] = "\nicedem: interrupted\n";
    [[maybe_unused]] const ssize_t n = ::write(2, msg, sizeof msg - 1);
  }
  ::_exit(128 + signal);
}

}  // namespace

OutputLock::OutputLock(const std::string& path) : path_(path) {
  std::error_code ec;
  created_ = !std::filesystem::exists(path, ec);
  // the handlers first: a signal between creating the file and installing them left an empty
  // output file behind (the process ended by the signal's default action)
  if (path.size() < sizeof g_path) {
    std::memcpy(g_path, path.c_str(), path.size() + 1);
    g_remove = created_ ? 1 : 0;
  }
  previous_int_ = std::signal(SIGINT, on_signal_before_the_run);
  previous_term_ = std::signal(SIGTERM, on_signal_before_the_run);
  auto give_up = [this] {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
    g_remove = 0;
  };
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    const int err = errno;
    give_up();
    throw OutputError(fmt::format("cannot open output file '{}': {}", path, std::strerror(err)));
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    give_up();
    if (err == EWOULDBLOCK)
      throw InputError(fmt::format("-o {}: another icedem run is writing this file; wait for it to end or "
                                   "choose another output file",
                                   path));
    throw OutputError(fmt::format("cannot lock output file '{}': {}", path, std::strerror(err)));
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
  g_remove = 0;
  struct stat st {};
  if (created_ && ::fstat(fd_, &st) == 0 && st.st_size == 0) ::unlink(path_.c_str());
  ::close(fd_);  // releases the lock
}

}  // namespace icedem
