#pragma once
// Output written beside its target and renamed onto it only when complete, so that a run that
// fails leaves no file (and no half-written one) under the target's name; a SIGINT or SIGTERM
// removes it too (interrupt_cleanup.hpp).

#include <filesystem>
#include <fstream>

namespace gp::cli {

class PartialFile {
 public:
  /// Opens TARGET.partial beside `target` for writing. Throws InputError naming "--out" when
  /// `target` is a directory or the partial file cannot be created.
  explicit PartialFile(std::filesystem::path target);
  /// Removes the partial file unless it was committed.
  ~PartialFile();
  PartialFile(const PartialFile&) = delete;
  PartialFile& operator=(const PartialFile&) = delete;

  std::ostream& stream() { return out_; }

  /// Closes the file and renames it onto the target. Throws std::runtime_error when a write
  /// failed (e.g. the disk is full).
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path partial_;
  std::ofstream out_;
  bool committed_ = false;
  int interrupt_slot_;  ///< the partial file's registration with the interrupt handler
};

}  // namespace gp::cli
