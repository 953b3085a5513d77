#pragma once
// What a run says when SIGINT, SIGTERM or SIGHUP ends it: that it stopped, where its results
// are and how to continue. The run then ends as the signal would (its exit status says so).

#include <string>

namespace wheelwear::cli {

/// Until the guard is destroyed, SIGINT, SIGTERM and SIGHUP print "wheelwear: stopped by
/// SIG...; the steps finished so far are in OUTPUT; continue with: wheelwear run --resume
/// OUTPUT" (or, before the first step is written, that there is nothing to resume yet) and then
/// end the process with that signal's default action. Signals the process
/// ignores (a shell's background job ignores SIGINT) stay ignored.
class StopMessage {
 public:
  /// Before steps_written() the message says that no step was written yet.
  explicit StopMessage(const std::string& output);
  /// What follows "wheelwear: stopped by SIG...": once steps are written, and before.
  struct Texts {
    std::string written, early;
  };
  explicit StopMessage(const Texts& texts);
  /// From now on the output holds finished steps (call it once a step is written, or at once
  /// when resuming); async-signal-safe.
  static void steps_written();
  ~StopMessage();
  StopMessage(const StopMessage&) = delete;
  StopMessage& operator=(const StopMessage&) = delete;
};

}  // namespace wheelwear::cli
