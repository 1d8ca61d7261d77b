#include "dem/output_lock.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "dem/errors.hpp"

namespace icedem {

OutputLock::OutputLock(const std::string& path) : path_(path) {
  std::error_code ec;
  created_ = !std::filesystem::exists(path, ec);
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw OutputError(fmt::format("cannot open output file '{}': {}", path, std::strerror(errno)));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw InputError(fmt::format("-o {}: another icedem run is writing this file; wait for it to end or "
                                   "choose another output file",
                                   path));
    throw OutputError(fmt::format("cannot lock output file '{}': {}", path, std::strerror(err)));
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  struct stat st {};
  if (created_ && ::fstat(fd_, &st) == 0 && st.st_size == 0) ::unlink(path_.c_str());
  ::close(fd_);  // releases the lock
}

}  // namespace icedem
