#include "cli/interrupt_cleanup.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>
#include <stdexcept>

namespace gp::cli {

namespace {

// A slot is free, being filled (the handler must not read its path yet) or armed.
enum SlotState : int { kFree, kFilling, kArmed };

struct Slot {
  std::atomic<int> state{kFree};
  std::array<char, 4096> path{};
};

// Fixed storage: the handler cannot allocate. A command writes a handful of files at once.
std::array<Slot, 16> slots;

void write_text(const char* text) {
  const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
  (void)ignored;  // nothing to do about a failed write on the way out
}

extern "C" void on_interrupt(int signal) {
  int removed = 0;
  for (Slot& slot : slots) {
    if (slot.state.load(std::memory_order_acquire) == kArmed && ::unlink(slot.path.data()) == 0) {
      ++removed;
    }
  }
  write_text(signal == SIGINT ? "interrupted (SIGINT)" : "interrupted (SIGTERM)");
  write_text(removed ? ": partial output removed, completed files kept\n"
                     : ": no partial output to remove\n");
  ::_exit(128 + signal);
}

}  // namespace

void install_interrupt_cleanup() {
  static std::once_flag installed;
  std::call_once(installed, [] {
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
  });
}

int remove_on_interrupt(const std::filesystem::path& path) {
  install_interrupt_cleanup();
  const std::string text = path.string();
  for (std::size_t i = 0; i < slots.size(); ++i) {
    int expected = kFree;
    if (!slots[i].state.compare_exchange_strong(expected, kFilling)) continue;
    if (text.size() >= slots[i].path.size()) {
      slots[i].state.store(kFree);
      throw std::runtime_error("path too long to clean up on interrupt: " + text);
    }
    std::memcpy(slots[i].path.data(), text.c_str(), text.size() + 1);
    slots[i].state.store(kArmed, std::memory_order_release);
    return static_cast<int>(i);
  }
  throw std::runtime_error("too many partial files open at once");
}

void release_on_interrupt(int slot) {
  slots.at(static_cast<std::size_t>(slot)).state.store(kFree);
}

}  // namespace gp::cli
