#include "stop_message.hpp"

#include <unistd.h>

#include <algorithm>
#include <array>
#include <csignal>
#include <cstring>

namespace wheelwear::cli {

namespace {

constexpr std::array<int, 3> kStopSignals{SIGINT, SIGTERM, SIGHUP};

// Prepared before the run: a signal handler may only write what is already there.
char g_stop_message[2048];
std::size_t g_stop_length = 0;
char g_stop_early[2048];
std::size_t g_stop_early_length = 0;
volatile std::sig_atomic_t g_stop_written = 0;
std::array<struct sigaction, kStopSignals.size()> g_stop_previous{};

const char* stop_signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "SIGHUP";
  }
}

extern "C" void stop_on_signal(int signal) {
  const char* prefix = "\nwheelwear: stopped by ";
  const char* name = stop_signal_name(signal);
  [[maybe_unused]] ssize_t n = ::write(STDERR_FILENO, prefix, std::strlen(prefix));
  n = ::write(STDERR_FILENO, name, std::strlen(name));
  if (g_stop_written)
    n = ::write(STDERR_FILENO, g_stop_message, g_stop_length);
  else
    n = ::write(STDERR_FILENO, g_stop_early, g_stop_early_length);
  std::signal(signal, SIG_DFL);
  ::raise(signal);
}

}  // namespace

StopMessage::StopMessage(const std::string& output)
    : StopMessage(Texts{"; the steps finished so far are in " + output +
                            "; continue with: wheelwear run --resume " + output + "\n",
                        " before the first step was written to " + output +
                            "; run it again (with --overwrite if the file exists)\n"}) {}

StopMessage::StopMessage(const Texts& texts) {
  const std::string& text = texts.written;
  g_stop_length = std::min(text.size(), sizeof g_stop_message);
  std::memcpy(g_stop_message, text.data(), g_stop_length);
  const std::string& early = texts.early;
  g_stop_early_length = std::min(early.size(), sizeof g_stop_early);
  std::memcpy(g_stop_early, early.data(), g_stop_early_length);
  g_stop_written = 0;
  for (std::size_t i = 0; i < kStopSignals.size(); ++i) {
    sigaction(kStopSignals[i], nullptr, &g_stop_previous[i]);
    if (g_stop_previous[i].sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = stop_on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(kStopSignals[i], &action, nullptr);
  }
}

void StopMessage::steps_written() {
  g_stop_written = 1;
}

StopMessage::~StopMessage() {
  for (std::size_t i = 0; i < kStopSignals.size(); ++i)
    sigaction(kStopSignals[i], &g_stop_previous[i], nullptr);
}

}  // namespace wheelwear::cli
