#pragma once
/// One writer per results file: a run holds an exclusive lock on `OUTPUT.lock` while it writes
/// OUTPUT, so that a second run (or a resume) given the same output stops with a clear error
/// instead of interleaving its steps with the first's. Manual: docs/results.md, "One writer".

#include <filesystem>
#include <string>

namespace wheelwear::pipeline {

/// The lock file of `output`: `output` + ".lock".
std::filesystem::path lock_path(const std::filesystem::path& output);

/// An exclusive flock(2) on lock_path(output), taken on construction and released, with the
/// lock file removed, on destruction. The file holds the locking process's id for the message
/// a second writer gets. flock is advisory and local to a machine; on network file systems
/// Linux maps it to the server's byte-range locks (NFS v4), so runs on different machines
/// exclude each other only where the server supports them.
class OutputLock {
 public:
  /// Takes the lock. Throws InputError naming the output and the cause when `output` is a
  /// folder, its folder does not exist or cannot be written, or another process holds the
  /// lock (naming its process id). Where the file system has no locks (flock fails with
  /// ENOLCK or EOPNOTSUPP), the run goes on unprotected and warning() says so.
  explicit OutputLock(const std::filesystem::path& output);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  /// Empty, or why the output is not protected.
  const std::string& warning() const { return warning_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::string warning_;
};

}  // namespace wheelwear::pipeline
