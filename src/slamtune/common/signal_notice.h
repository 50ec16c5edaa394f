// A last line for SIGINT and SIGTERM: while a SignalNotice lives, either signal prints
// "slamtune: stopped by SIGINT; LINE" (or SIGTERM) on stderr and then ends the process by
// the signal's default action, so the parent sees the signal (a shell reports status 130 /
// 143).
//
// Why: a long command whose work is committed as it goes (optimize's run database) loses
// nothing when stopped, but a silent stop leaves the user to guess whether and how to go on.
// The handler only writes and re-raises (both async-signal-safe); whatever the process had
// committed stands, and anything uncommitted is discarded as after kill -9.
#pragma once

#include <string>

namespace slamtune {

class SignalNotice {
 public:
  // Installs the handlers; `line` (at most 900 bytes are kept) is what to tell the user.
  explicit SignalNotice(const std::string& line);
  ~SignalNotice();  // restores the handlers that were installed before
  SignalNotice(const SignalNotice&) = delete;
  SignalNotice& operator=(const SignalNotice&) = delete;
};

}  // namespace slamtune
