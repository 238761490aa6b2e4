// An output directory written as one unit: a run writes every file into a temporary
// sibling (DIR.tmp-PID) and Commit() puts it in place of DIR, so a run that is killed leaves
// either the previous complete DIR or none (a crash between the two renames leaves the
// previous output as DIR.old-PID, which the next run restores), never a mixture of old and
// new files or a half-written set. Begin() checks up front that DIR can be written and
// clears the temporaries of runs that are no longer alive.
#pragma once

#include <string>

namespace ergo {

class OutputDirectory {
 public:
  // Prepares `final_path` (throws InputError naming `flag` when it cannot be written: a file
  // is in the way, a parent is not writable, or it lies under /proc, /sys or /dev).
  OutputDirectory(const std::string& final_path, const std::string& flag);
  // Removes the temporary directory unless Commit() succeeded.
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  // Where the run writes its files (the temporary sibling).
  const std::string& path() const { return temporary_; }
  const std::string& final_path() const { return final_; }
  // Replaces DIR by the temporary directory. Returns false with *error set on failure.
  bool Commit(std::string* error);

 private:
  std::string final_;
  std::string temporary_;
  bool committed_ = false;
};

}  // namespace ergo
