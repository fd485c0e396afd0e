#pragma once
/// @file pending_temp_files.hpp
/// @brief The temporary files being written right now, removed by a SIGINT/SIGTERM handler before
/// the signal ends the process: an interrupted write of a large image leaves nothing behind.
/// The handler only calls unlink, signal and raise (async-signal-safe) on fixed storage.
#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>

#include <signal.h>
#include <unistd.h>

namespace lucent::io {

class PendingTempFiles {
 public:
  /// Registers `path` (installing the handler, chained to the one it replaces); returns its slot,
  /// -1 when all slots are taken or the path is too long (it is then removed on normal exits only).
  static int add(const std::string& path) {
    install();
    if (path.size() >= kPathBytes) return -1;
    for (int i = 0; i < kSlots; ++i) {
      bool expected = false;
      if (!slots()[i].claimed.compare_exchange_strong(expected, true)) continue;
      std::memcpy(slots()[i].path, path.c_str(), path.size() + 1);
      slots()[i].ready.store(true);
      return i;
    }
    return -1;
  }

  static void remove(int slot) {
    if (slot < 0) return;
    slots()[slot].ready.store(false);
    slots()[slot].claimed.store(false);
  }

  /// Puts the handler on SIGINT and SIGTERM unless it is there already, keeping what it replaces
  /// (a host application's handler runs after the files are removed; the default ends the process).
  static void install() {
    slots();  // the table exists before the handler can run
    for (int k = 0; k < 2; ++k) {
      struct sigaction current {};
      sigaction(kSignals[k], nullptr, &current);
      if ((current.sa_flags & SA_SIGINFO) && current.sa_sigaction == &onSignal) continue;
      if (!(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_IGN) continue;  // nohup
      previous()[k] = current;
      struct sigaction action {};
      action.sa_sigaction = &onSignal;
      action.sa_flags = SA_SIGINFO | SA_RESTART;  // a chained handler may return: writes go on
      sigemptyset(&action.sa_mask);
      sigaction(kSignals[k], &action, nullptr);
    }
  }

 private:
  static constexpr int kSlots = 32;
  static constexpr std::size_t kPathBytes = 4096;
  static constexpr int kSignals[2] = {SIGINT, SIGTERM};
  struct Slot {
    std::atomic<bool> claimed{false}, ready{false};
    char path[kPathBytes];
  };
  static Slot* slots() {
    static Slot table[kSlots];
    return table;
  }
  static struct sigaction* previous() {
    static struct sigaction table[2] = {};
    return table;
  }

  static void onSignal(int sig, siginfo_t* info, void* context) {
    const int savedErrno = errno;
    for (int i = 0; i < kSlots; ++i)
      if (slots()[i].ready.load()) ::unlink(slots()[i].path);
    errno = savedErrno;
    const struct sigaction& before = previous()[sig == SIGINT ? 0 : 1];
    if (before.sa_flags & SA_SIGINFO) return before.sa_sigaction(sig, info, context);
    if (before.sa_handler == SIG_IGN) return;
    if (before.sa_handler != SIG_DFL) return before.sa_handler(sig);
    ::signal(sig, SIG_DFL);  // then end as the signal would have
    ::raise(sig);
  }
};

}  // namespace lucent::io
