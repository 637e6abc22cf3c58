#include "cli/partial_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "cli/interrupt_cleanup.hpp"
#include "scene/input_error.hpp"

namespace gp::cli {

PartialFile::PartialFile(std::filesystem::path target) : target_(std::move(target)) {
  if (std::filesystem::is_directory(target_)) {
    throw InputError("--out", "must be a file, not a directory", target_.string());
  }
  partial_ = target_;
  partial_ += ".partial";
  interrupt_slot_ = remove_on_interrupt(partial_);
  out_.open(partial_, std::ios::binary);
  if (!out_.is_open()) {
    release_on_interrupt(interrupt_slot_);
    throw InputError("--out", std::string("must be a writable file (") + std::strerror(errno) + ")",
                     target_.string());
  }
}

PartialFile::~PartialFile() {
  if (committed_) return;
  out_.close();
  std::error_code ignored;  // nothing more can be done about a leftover in a destructor
  std::filesystem::remove(partial_, ignored);
  release_on_interrupt(interrupt_slot_);
}

void PartialFile::commit() {
  out_.close();
  if (out_.fail()) throw std::runtime_error("cannot write " + partial_.string());
  std::filesystem::rename(partial_, target_);
  committed_ = true;
  release_on_interrupt(interrupt_slot_);
}

}  // namespace gp::cli
