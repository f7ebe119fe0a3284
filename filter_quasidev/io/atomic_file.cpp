#include "io/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "common/error.h"

namespace qd::io {

namespace {

std::string reason() { return std::strerror(errno); }

// Mode of a newly created file under the current umask (mkstemp itself gives 0600).
mode_t new_file_mode() {
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return static_cast<mode_t>(0666 & ~mask);
}

// Writes all of `content` to fd; false on any error.
bool write_all(int fd, const std::string& content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

PendingFile::PendingFile(const std::string& target, const std::string& content) : target_(target) {
  std::vector<char> name(target.begin(), target.end());
  const std::string suffix = ".quasidev-tmp-XXXXXX";
  name.insert(name.end(), suffix.begin(), suffix.end());
  name.push_back('\0');
  const int fd = ::mkstemp(name.data());
  if (fd < 0) throw common::Error("cannot create a file next to '" + target + "': " + reason());
  temp_ = name.data();
  ::fchmod(fd, new_file_mode());
  const bool ok = write_all(fd, content) && ::fsync(fd) == 0;
  const std::string why = reason();
  if (::close(fd) != 0 || !ok) {
    std::remove(temp_.c_str());
    throw common::Error("cannot write '" + target + "': " + why);
  }
}

PendingFile::~PendingFile() {
  if (!committed_) std::remove(temp_.c_str());
}

void PendingFile::commit() {
  if (std::rename(temp_.c_str(), target_.c_str()) != 0)
    throw common::Error("cannot move the new file into place as '" + target_ + "': " + reason());
  committed_ = true;
}

}  // namespace qd::io
