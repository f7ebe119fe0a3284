// Atomic file output: the content goes to a temporary file in the target's directory, which is
// renamed over the target only by commit(). Until then the target is untouched; a PendingFile
// destroyed without commit() removes its temporary file.
// Throws qd::common::Error if the temporary file cannot be created or written, or the rename fails.
#pragma once

#include <string>

namespace qd::io {

class PendingFile {
 public:
  PendingFile(const std::string& target, const std::string& content);
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  void commit();

 private:
  std::string target_;
  std::string temp_;
  bool committed_ = false;
};

}  // namespace qd::io
