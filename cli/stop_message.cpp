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

// The message goes out in one write: under mpirun a process's stderr is forwarded in the pieces
// it was written in, and Open MPI's own report of the signal could land between them.
// (memcpy and strlen are async-signal-safe, POSIX.1-2016.)
extern "C" void stop_on_signal(int signal) {
  char text[sizeof g_stop_message + 64];
  std::size_t length = 0;
  const auto append = [&](const char* part, std::size_t size) {
    size = std::min(size, sizeof text - length);
    std::memcpy(text + length, part, size);
    length += size;
  };
  const char* prefix = "\nwheelwear: stopped by ";
  const char* name = stop_signal_name(signal);
  append(prefix, std::strlen(prefix));
  append(name, std::strlen(name));
  if (g_stop_written)
    append(g_stop_message, g_stop_length);
  else
    append(g_stop_early, g_stop_early_length);
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, text, length);
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
