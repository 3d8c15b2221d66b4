#pragma once
// Running a program the way a student, a grader or a benchmark does: with its output captured to
// files and a few environment variables changed. For the test and benchmark tools (lesson_check,
// shadowlab_bench, frame_bench), which run the real lesson programs.
#include <cstddef>
#include <string>
#include <vector>

namespace shadowlab {

struct ProcessOptions {
  std::string stdoutPath;             // "" : inherit
  std::string stderrPath;             // "" : the same file as stdout (or inherit)
  std::vector<std::string> setEnv;    // "NAME=value", added or replacing
  std::vector<std::string> unsetEnv;  // names removed from the environment
  double* cpuSeconds = nullptr;       // if set: the user + system CPU time the process (all its threads) used
  bool wait = true;                   // false: start it and return 0 at once (the launcher's lessons)
  // Limits for code we do not trust (a student's, in the graders): past timeoutSeconds (> 0) the
  // process is killed (SIGKILL; TerminateProcess) and *timedOut set; memoryLimitMb (> 0) caps its
  // address space (RLIMIT_AS; a job object's process memory on Windows) and makes it a group of
  // its own (a process group; the job object): whatever it started and left running is killed
  // when it ends, so nothing it leaves behind can touch files once its results are read.
  double timeoutSeconds = 0;
  std::size_t memoryLimitMb = 0;
  bool* timedOut = nullptr;
};

// Runs args[0] (a path, not looked up in PATH) with args; returns its exit code, 128 + the signal
// when it was killed (POSIX; on Windows a crash's exception code, e.g. 0xC0000005), or -1 when it
// could not be started. posix_spawn on POSIX systems, CreateProcessW on Windows.
int runProcess(const std::vector<std::string>& args, const ProcessOptions& options = {});

// Collects the processes started with wait = false that have ended, so none lingers (POSIX zombies);
// returns at once. Nothing to do on Windows.
void reapFinishedProcesses();

// Opens a file (a README, a slide deck) with the desktop's viewer: xdg-open on Linux, open on
// macOS, the shell's association on Windows. False when no viewer could be started.
bool openWithDesktop(const std::string& path);

// A tool's first argument, the program it runs (lesson_check, psm_stress): "--help" or "-h" prints
// `usage` on stdout and returns 0; absent or not a file, it is named on stderr with the usage and
// 2 returned (a flag there is not a program to start); -1 when it is a file: go on.
int checkProgramArgument(const char* tool, int argc, char** argv, const char* usage);

}  // namespace shadowlab
