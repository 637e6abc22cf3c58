#pragma once
// What a command does on SIGINT or SIGTERM: remove the partial files it is writing, print one line
// and exit 130 or 143 (128 + the signal), so that a stopped run leaves no half-written file behind.
// The handler only unlinks registered paths, writes and calls _exit: all async-signal-safe.

#include <filesystem>

namespace gp::cli {

/// Installs the handler of SIGINT and SIGTERM (once; later calls do nothing).
void install_interrupt_cleanup();

/// Installs the handler and registers `path` to be removed if a signal arrives before
/// release_on_interrupt(slot). Returns the slot. Throws std::runtime_error when every slot is
/// taken.
int remove_on_interrupt(const std::filesystem::path& path);

/// Forgets the path of `slot` (the file was committed or removed).
void release_on_interrupt(int slot);

}  // namespace gp::cli
