#include "slamtune/common/signal_notice.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>

namespace slamtune {
namespace {

// Written by the constructor before the handlers are installed, read only by the handler.
char g_line[1024];
std::size_t g_length = 0;
bool g_end_live_line = false;  // stderr is a terminal: a live progress line is ended first
struct sigaction g_previous_int, g_previous_term;

void Write(const char* text, std::size_t length) {
  while (length > 0) {
    const ssize_t n = write(STDERR_FILENO, text, length);
    if (n <= 0) return;
    text += n;
    length -= static_cast<std::size_t>(n);
  }
}

extern "C" void OnSignal(int signal_number) {
  if (g_end_live_line) Write("\n", 1);
  const char* prefix = signal_number == SIGINT ? "slamtune: stopped by SIGINT; " : "slamtune: stopped by SIGTERM; ";
  Write(prefix, std::strlen(prefix));
  Write(g_line, g_length);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

}  // namespace

SignalNotice::SignalNotice(const std::string& line) {
  const std::string text = line.substr(0, 900) + "\n";
  g_end_live_line = isatty(STDERR_FILENO) != 0;
  g_length = std::min(text.size(), sizeof(g_line));
  std::memcpy(g_line, text.data(), g_length);
  struct sigaction action {};
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

SignalNotice::~SignalNotice() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

}  // namespace slamtune
