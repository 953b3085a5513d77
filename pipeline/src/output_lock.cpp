#include "wheelwear/pipeline/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "wheelwear/core/input_error.hpp"

namespace fs = std::filesystem;

namespace wheelwear::pipeline {

namespace {

// The process id a lock file records, or "unknown".
std::string holder(int fd) {
  char text[32] = {};
  const ssize_t n = pread(fd, text, sizeof text - 1, 0);
  std::string pid = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string();
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.empty() ? "unknown" : pid;
}

// The folder `output` is written in, for messages.
std::string folder_of(const fs::path& output) {
  const fs::path parent = output.parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

}  // namespace

fs::path lock_path(const fs::path& output) {
  fs::path lock = output;
  lock += ".lock";
  return lock;
}

OutputLock::OutputLock(const fs::path& output) : path_(lock_path(output)) {
  std::error_code ignored;
  if (fs::is_directory(output, ignored))
    throw InputError("output " + output.string() + ": is a folder; give a file name, e.g. " +
                     (output / "run.h5").string());
  while (true) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) {
      const int error = errno;
      if (error == ENOENT)
        throw InputError("output " + output.string() + ": the folder " + folder_of(output) +
                         " does not exist; create it or choose another output");
      if (error == ENOTDIR)
        throw InputError("output " + output.string() + ": " + folder_of(output) +
                         " is not a folder; choose another output");
      throw IoError("output " + output.string() + ": cannot write in the folder " +
                    folder_of(output) + " (" + std::strerror(error) +
                    "); choose a writable folder");
    }
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      if (error == EWOULDBLOCK) {
        const std::string pid = holder(fd_);
        ::close(fd_);
        fd_ = -1;
        throw IoError("output " + output.string() + ": another run is writing it (process " + pid +
                      ", lock " + path_.string() +
                      "); wait for it to end or choose another output");
      }
      if (error == ENOLCK || error == EOPNOTSUPP) {
        warning_ = "output " + output.string() + ": the file system has no locks (" +
                   std::strerror(error) +
                   "); nothing stops a second run from writing the same output";
        break;
      }
      ::close(fd_);
      fd_ = -1;
      throw IoError("output " + output.string() + ": cannot lock " + path_.string() + " (" +
                    std::strerror(error) + ")");
    }
    // The run that held the lock may have removed the file before this one locked it: only a
    // lock on the file that is there now counts.
    struct stat held {
    }, present{};
    if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &present) == 0 &&
        held.st_dev == present.st_dev && held.st_ino == present.st_ino)
      break;
    ::close(fd_);
    fd_ = -1;
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) == 0) {
    [[maybe_unused]] const ssize_t written = ::pwrite(fd_, pid.data(), pid.size(), 0);
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  // Removed while still held: a process waiting on the old file finds it gone and retries.
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace wheelwear::pipeline
