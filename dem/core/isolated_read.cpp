#include "dem/core/isolated_read.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>

#include <fmt/format.h>

namespace icedem {
namespace {

void write_all(int fd, const std::string& s) {
  for (std::size_t done = 0; done < s.size();) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

IsolatedResult read_isolated(const std::function<std::string()>& reader, double timeout_s) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) return {false, fmt::format("cannot make a pipe: {}", std::strerror(errno))};
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    return {false, fmt::format("cannot fork: {}", std::strerror(errno))};
  }
  if (child == 0) {  // the child: one byte of verdict, then the text; never returns
    ::close(pipe_fds[0]);
    ::signal(SIGINT, SIG_DFL);  // the parent's handlers (a run's) are not the child's
    ::signal(SIGTERM, SIG_DFL);
    std::string out;
    try {
      out = "+" + reader();
    } catch (const std::exception& e) {
      out = std::string("-") + e.what();
    } catch (...) {
      out = "-an unknown exception";
    }
    write_all(pipe_fds[1], out);
    ::_exit(0);  // no destructors, no atexit handlers of the parent's
  }
  ::close(pipe_fds[1]);
  std::string text;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  bool timed_out = false;
  for (char buffer[65536];;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd p{pipe_fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(pipe_fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the child closed its end: done or dead
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  if (timed_out) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out) return {false, fmt::format("reading it did not end within {:.0f} s", timeout_s)};
  if (WIFSIGNALED(status))
    return {false, "the HDF5 library failed on it"};  // a crash of the reader: the signal is not the user's business
  if (text.empty()) return {false, "the reader ended without an answer"};
  return {text[0] == '+', text.substr(1)};
}

}  // namespace icedem
