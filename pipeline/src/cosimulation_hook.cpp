#include "wheelwear/pipeline/cosimulation_hook.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <optional>
#include <string_view>
#include <thread>
#include <vector>

#include "wheelwear/core/input_error.hpp"
#include "wheelwear/core/text.hpp"
#include "wheelwear/profiles/profile_io.hpp"

extern char** environ;

namespace wheelwear::pipeline {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kLogTail = 64 * 1024;  // bytes of the program's output kept
constexpr const char* kLogName = "hook.log";

// The file name's extension for `body`: MiniProf and SIMPACK name the body in it.
std::string extension(HookProfileFormat format, profiles::Body body) {
  const bool wheel = body == profiles::Body::wheel;
  switch (format) {
    case HookProfileFormat::simpack:
      return wheel ? ".prw" : ".prr";
    case HookProfileFormat::miniprof:
      return wheel ? ".whl" : ".ban";
    case HookProfileFormat::csv:
      break;
  }
  return ".csv";
}

std::string replaced(std::string argument,
                     const std::vector<std::pair<std::string, std::string>>& values) {
  for (const auto& [name, value] : values) {
    const std::string token = "{" + name + "}";
    for (std::size_t at = argument.find(token); at != std::string::npos;
         at = argument.find(token, at + value.size()))
      argument.replace(at, token.size(), value);
  }
  return argument;
}

std::string tail(const fs::path& log) {
  std::error_code error;
  if (!fs::is_regular_file(log, error) || fs::file_size(log, error) == 0 || error) return {};
  std::string text = core::read_text_file(log);
  if (text.size() > kLogTail) text.erase(0, text.size() - kLogTail);
  return text;
}

// The last few lines of the program's output, for an error message.
std::string last_lines(const std::string& log, int count) {
  std::size_t at = log.size();
  while (at > 0 && (log[at - 1] == '\n' || log[at - 1] == '\r')) --at;
  const std::size_t end = at;
  for (int i = 0; i < count && at > 0; ++i) {
    at = log.rfind('\n', at - 1);
    if (at == std::string::npos) {
      at = 0;
      break;
    }
  }
  const std::string lines = log.substr(at, end - at);
  return lines.empty() ? "(no output)" : lines;
}

// The program's process group while it runs: killed and reaped when the call ends early (an
// exception, or the run itself interrupted), so no program outlives the run that started it.
class ProgramGroup {
 public:
  explicit ProgramGroup(pid_t pid) : pid_(pid) {}
  ProgramGroup(const ProgramGroup&) = delete;
  ProgramGroup& operator=(const ProgramGroup&) = delete;
  ~ProgramGroup() {
    if (pid_ > 0) end();
  }
  // Kills the whole group and reaps the program; returns its wait status.
  int end() {
    kill(-pid_, SIGKILL);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = 0;
    return status;
  }
  // The program's wait status once it has exited, else nullopt.
  std::optional<int> poll() {
    int status = 0;
    const pid_t done = waitpid(pid_, &status, WNOHANG);
    if (done == pid_) {
      pid_ = 0;
      return status;
    }
    if (done < 0 && errno != EINTR)
      throw InputError(std::string("[hook] command: lost the program: ") + std::strerror(errno));
    return std::nullopt;
  }

 private:
  pid_t pid_;
};

// SIGINT, SIGTERM and SIGHUP while a program runs in its own process group (which the terminal's
// Ctrl-C does not reach): noted here, the program's group killed, and the signal raised again
// with its former disposition, so the run ends as it would have.
volatile std::sig_atomic_t interrupted = 0;
extern "C" void note_interrupt(int signal) {
  interrupted = signal;
}

class InterruptForwarding {
 public:
  InterruptForwarding() {
    interrupted = 0;
    struct sigaction action {};
    action.sa_handler = note_interrupt;
    sigemptyset(&action.sa_mask);
    // A signal the run ignores (as a shell's background job ignores SIGINT) stays ignored.
    for (std::size_t i = 0; i < kSignals.size(); ++i) {
      sigaction(kSignals[i], nullptr, &former_[i]);
      if (former_[i].sa_handler != SIG_IGN) sigaction(kSignals[i], &action, nullptr);
    }
  }
  InterruptForwarding(const InterruptForwarding&) = delete;
  InterruptForwarding& operator=(const InterruptForwarding&) = delete;
  ~InterruptForwarding() { restore(); }
  // Puts the former dispositions back.
  void restore() {
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &former_[i], nullptr);
  }

 private:
  static constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};
  std::array<struct sigaction, 3> former_{};
};

// Starts `arguments` in `working_directory`, in a process group of its own, with standard
// output and error into `log`; throws InputError naming what failed.
pid_t start_program(const std::vector<std::string>& arguments, const fs::path& working_directory,
                    const fs::path& log) {
  if (!fs::is_directory(working_directory))
    throw InputError("[hook] command: its working directory " + working_directory.string() +
                     " (the scene's) does not exist");
  const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (out < 0)
    throw InputError("[hook]: cannot write its log " + log.string() + ": " + std::strerror(errno));
  std::vector<char*> argv;
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, out, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out, STDERR_FILENO);
  // The program runs in the scene's directory, where relative names in a scene are taken from;
  // the run's own working directory stays as it is.
  posix_spawn_file_actions_addchdir_np(&actions, working_directory.c_str());
  // Its own process group, so that a timeout ends whatever the program started as well.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  // Without the MPI launcher's variables: the program is not a process of this run's job (an MPI
  // program, wheelwear among them, would take itself for one and wait for the others).
  std::vector<char*> environment;
  for (char** variable = environ; *variable; ++variable) {
    const std::string_view name(*variable);
    if (!name.starts_with("OMPI_") && !name.starts_with("PMIX_") && !name.starts_with("PMI_"))
      environment.push_back(*variable);
  }
  environment.push_back(nullptr);
  pid_t pid = 0;
  const int started =
      posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(), environment.data());
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  close(out);
  if (started != 0)
    throw InputError("[hook] command: cannot start " + arguments.front() + ": " +
                     std::strerror(started) + " (give the program's path or put it on PATH)");
  return pid;
}

// Runs `arguments` (start_program) and returns its wait status; throws when it runs past
// `timeout`, and passes an interrupt of the run on to the program's group.
int run_program(const std::vector<std::string>& arguments, const fs::path& working_directory,
                const fs::path& log, double timeout) {
  InterruptForwarding forwarding;
  ProgramGroup program(start_program(arguments, working_directory, log));
  const auto t0 = std::chrono::steady_clock::now();
  while (true) {
    if (const std::optional<int> status = program.poll()) return *status;
    if (const int signal = interrupted) {
      program.end();
      forwarding.restore();
      std::raise(signal);  // ends the run, unless someone else handles it
      throw InputError("[hook]: the run was interrupted (signal " + std::to_string(signal) +
                       ") while its program ran; the program was ended");
    }
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > timeout) {
      program.end();
      throw InputError("[hook] command `" + hook_command_line(arguments) +
                       "` ran past its timeout of " + core::format_number(timeout) +
                       " s and was killed; raise [hook] timeout_s if it needs longer. Its last "
                       "output:\n" +
                       last_lines(tail(log), 10));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace

std::string hook_command_line(const std::vector<std::string>& arguments) {
  std::string out;
  for (const std::string& a : arguments) out += (out.empty() ? "" : " ") + a;
  return out;
}

const std::vector<std::pair<std::string, std::string>>& hook_placeholders() {
  static const std::vector<std::pair<std::string, std::string>> names{
      {"wheel", "the wheel profile file (the left wheel's when the wheels are separate)"},
      {"wheel_left", "the left wheel's profile file"},
      {"wheel_right", "the right wheel's profile file"},
      {"rail", "the rail profile file (both rails, inclined as the run uses it)"},
      {"collective", "the file the program must write the step's collective to (CSV)"},
      {"step", "the step number, from 0"},
      {"distance_m", "the running distance at the step [m]"},
      {"directory", "the step's directory, where these files are"},
  };
  return names;
}

void validate_hook_command(const std::vector<std::string>& command) {
  if (command.empty() || command.front().empty())
    throw InputError(
        "[hook] command: give the program and its arguments as a list of "
        "strings, e.g. [\"python3\", \"mbs_batch.py\", \"{wheel}\", \"{rail}\", "
        "\"{collective}\"]");
  bool collective = false;
  for (const std::string& argument : command) {
    for (std::size_t open = argument.find('{'); open != std::string::npos;
         open = argument.find('{', open + 1)) {
      const std::size_t close = argument.find('}', open);
      if (close == std::string::npos) break;
      const std::string name = argument.substr(open + 1, close - open - 1);
      bool known = false;
      for (const auto& [placeholder, what] : hook_placeholders()) known |= placeholder == name;
      if (!known) {
        std::string list;
        for (const auto& [placeholder, what] : hook_placeholders())
          list += (list.empty() ? "{" : ", {") + placeholder + "}";
        throw InputError("[hook] command: unknown placeholder {" + name + "} in \"" + argument +
                         "\"; the known ones are " + list);
      }
      collective |= name == "collective";
    }
  }
  if (!collective)
    throw InputError(
        "[hook] command: no argument names {collective}, the file the program "
        "must write the step's collective to; add it where the program expects "
        "its output file");
}

HookCall call_hook(const CosimulationHook& hook, const fs::path& directory, int step,
                   double distance, const HookProfiles& profiles) {
  validate_hook_command(hook.command);
  std::error_code error;
  fs::create_directories(directory, error);
  if (error || !fs::is_directory(directory))
    throw InputError("[hook]: cannot create its directory " + directory.string() + ": " +
                     error.message());
  const fs::path absolute = fs::absolute(directory);
  const std::string ext = extension(hook.profile_format, profiles::Body::wheel);
  const fs::path left = absolute / ("wheel_left" + ext), right = absolute / ("wheel_right" + ext);
  const fs::path rail = absolute / ("rail" + extension(hook.profile_format, profiles::Body::rail));
  const fs::path collective = absolute / "collective.csv";
  const fs::path log = absolute / kLogName;
  // An earlier call's collective must not pass for this one's.
  fs::remove(collective, error);
  profiles::write_profile_file(left, profiles.wheel_left, profiles::Body::wheel);
  profiles::write_profile_file(right, profiles.wheel_right, profiles::Body::wheel);
  profiles::write_profile_file(rail, profiles.rail, profiles::Body::rail);

  const std::vector<std::pair<std::string, std::string>> values{
      {"wheel_left", left.string()},
      {"wheel_right", right.string()},
      {"wheel", left.string()},
      {"rail", rail.string()},
      {"collective", collective.string()},
      {"step", std::to_string(step)},
      {"distance_m", core::format_number(distance)},
      {"directory", absolute.string()},
  };
  HookCall call;
  for (const std::string& argument : hook.command)
    call.arguments.push_back(replaced(argument, values));
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path working =
      hook.working_directory.empty() ? fs::current_path() : fs::absolute(hook.working_directory);
  const int status = run_program(call.arguments, working, log, hook.timeout);
  call.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  call.log = tail(log);
  const std::string command = "[hook] command `" + hook_command_line(call.arguments) + "`";
  if (WIFSIGNALED(status))
    throw InputError(command + " was ended by signal " + std::to_string(WTERMSIG(status)) +
                     " at step " + std::to_string(step) + ". Its last output:\n" +
                     last_lines(call.log, 10));
  if (WEXITSTATUS(status) != 0)
    throw InputError(command + " exited with status " + std::to_string(WEXITSTATUS(status)) +
                     " at step " + std::to_string(step) + ". Its last output:\n" +
                     last_lines(call.log, 10));
  if (!fs::is_regular_file(collective))
    throw InputError(command + " exited 0 at step " + std::to_string(step) +
                     " but wrote no collective to " + collective.string() +
                     " (the argument {collective}). Its last output:\n" + last_lines(call.log, 10));
  call.collective = core::read_text_file(collective);
  return call;
}

}  // namespace wheelwear::pipeline
