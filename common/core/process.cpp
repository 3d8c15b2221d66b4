#include "core/process.hpp"

#ifdef _WIN32
#include <windows.h>

#include <shellapi.h>  // after windows.h, which it needs
#else
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
extern char** environ;
#endif

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <thread>
#include <iostream>

namespace shadowlab {
namespace {

// The current environment with options.unsetEnv removed and options.setEnv added or replacing.
std::vector<std::string> childEnvironment(const std::vector<std::string>& current, const ProcessOptions& o) {
  std::vector<std::string> env;
  auto named = [](const std::string& entry, const std::string& name) { return entry.rfind(name + "=", 0) == 0; };
  for (const std::string& entry : current) {
    bool drop =
        std::any_of(o.unsetEnv.begin(), o.unsetEnv.end(), [&](const std::string& n) { return named(entry, n); });
    for (const auto& s : o.setEnv) drop = drop || named(entry, s.substr(0, s.find('=')));
    if (!drop) env.push_back(entry);
  }
  env.insert(env.end(), o.setEnv.begin(), o.setEnv.end());
  return env;
}

#ifdef _WIN32
std::wstring widen(const std::string& s) {
  if (s.empty()) return {};
  const int n = MultiByteToWideChar(CP_UTF8, 0, s.data(), int(s.size()), nullptr, 0);
  std::wstring w(std::size_t(n), L'\0');
  MultiByteToWideChar(CP_UTF8, 0, s.data(), int(s.size()), w.data(), n);
  return w;
}

std::string narrow(const std::wstring& w) {
  if (w.empty()) return {};
  const int n = WideCharToMultiByte(CP_UTF8, 0, w.data(), int(w.size()), nullptr, 0, nullptr, nullptr);
  std::string s(std::size_t(n), '\0');
  WideCharToMultiByte(CP_UTF8, 0, w.data(), int(w.size()), s.data(), n, nullptr, nullptr);
  return s;
}

std::vector<std::string> currentEnvironment() {
  std::vector<std::string> env;
  wchar_t* block = GetEnvironmentStringsW();
  for (const wchar_t* e = block; e && *e; e += std::wcslen(e) + 1)
    if (*e != L'=') env.push_back(narrow(e));  // "=C:=C:\..." entries are the shell's drive folders
  if (block) FreeEnvironmentStringsW(block);
  return env;
}

// One argument as CommandLineToArgvW (and the C runtime) will split it back.
std::wstring quoted(const std::wstring& arg) {
  if (!arg.empty() && arg.find_first_of(L" \t\n\v\"") == std::wstring::npos) return arg;
  std::wstring q = L"\"";
  for (auto it = arg.begin();; ++it) {
    std::size_t backslashes = 0;
    while (it != arg.end() && *it == L'\\') ++it, ++backslashes;
    if (it == arg.end()) {
      q.append(backslashes * 2, L'\\');
      break;
    }
    q.append(*it == L'"' ? backslashes * 2 + 1 : backslashes, L'\\');
    q.push_back(*it);
  }
  return q + L"\"";
}

HANDLE openOutput(const std::string& path) {
  SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
  return CreateFileW(widen(path).c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE, &inherit, CREATE_ALWAYS,
                     FILE_ATTRIBUTE_NORMAL, nullptr);
}

double seconds(const FILETIME& t) {  // 100 ns units
  return double((std::uint64_t(t.dwHighDateTime) << 32) | t.dwLowDateTime) * 1e-7;
}
#else
std::vector<std::string> currentEnvironment() {
  std::vector<std::string> env;
  for (char** e = environ; *e; ++e) env.emplace_back(*e);
  return env;
}
#endif

}  // namespace

#ifdef _WIN32
// Windows: CreateProcessW with the arguments quoted for CommandLineToArgvW. There are no signals:
// a crash exits with its exception code (0xC0000005 and so on), returned as it is.
int runProcess(const std::vector<std::string>& args, const ProcessOptions& o) {
  if (args.empty()) return -1;
  std::wstring commandLine;
  for (const auto& a : args) commandLine += (commandLine.empty() ? L"" : L" ") + quoted(widen(a));
  std::wstring block;
  for (const auto& e : childEnvironment(currentEnvironment(), o)) block += widen(e) + L'\0';
  block += L'\0';
  HANDLE out = o.stdoutPath.empty() ? GetStdHandle(STD_OUTPUT_HANDLE) : openOutput(o.stdoutPath);
  HANDLE err = !o.stderrPath.empty()   ? openOutput(o.stderrPath)
               : !o.stdoutPath.empty() ? out
                                       : GetStdHandle(STD_ERROR_HANDLE);
  STARTUPINFOW startup{};
  startup.cb = sizeof startup;
  startup.dwFlags = STARTF_USESTDHANDLES;
  startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
  startup.hStdOutput = out;
  startup.hStdError = err;
  PROCESS_INFORMATION process{};
  // A memory limit is a job object's: the process starts suspended, joins the job, then runs.
  HANDLE job = nullptr;
  if (o.memoryLimitMb > 0) {
    job = CreateJobObjectW(nullptr, nullptr);
    JOBOBJECT_EXTENDED_LIMIT_INFORMATION limit{};
    limit.BasicLimitInformation.LimitFlags = JOB_OBJECT_LIMIT_PROCESS_MEMORY | JOB_OBJECT_LIMIT_KILL_ON_JOB_CLOSE;
    limit.ProcessMemoryLimit = SIZE_T(o.memoryLimitMb) << 20;
    if (job) SetInformationJobObject(job, JobObjectExtendedLimitInformation, &limit, sizeof limit);
  }
  const DWORD flags = CREATE_UNICODE_ENVIRONMENT | (job ? CREATE_SUSPENDED : 0);
  const bool started = CreateProcessW(widen(args[0]).c_str(), commandLine.data(), nullptr, nullptr, TRUE, flags,
                                      block.data(), nullptr, &startup, &process);
  if (started && job) {
    AssignProcessToJobObject(job, process.hProcess);
    ResumeThread(process.hThread);
  }
  if (!o.stdoutPath.empty()) CloseHandle(out);
  if (!o.stderrPath.empty()) CloseHandle(err);
  if (!started) {
    if (job) CloseHandle(job);
    return -1;
  }
  if (o.timedOut) *o.timedOut = false;
  if (!o.wait) {
    CloseHandle(process.hThread);
    CloseHandle(process.hProcess);
    return 0;  // (a job's handle stays open: closing it would end the process)
  }
  const DWORD ms = o.timeoutSeconds > 0 ? DWORD(o.timeoutSeconds * 1000) : INFINITE;
  if (WaitForSingleObject(process.hProcess, ms) == WAIT_TIMEOUT) {
    TerminateProcess(process.hProcess, 0xC000013A);  // STATUS_CONTROL_C_EXIT, as a killed console program
    WaitForSingleObject(process.hProcess, INFINITE);
    if (o.timedOut) *o.timedOut = true;
  }
  DWORD code = 0;
  GetExitCodeProcess(process.hProcess, &code);
  FILETIME created, exited, kernel, user;
  if (o.cpuSeconds && GetProcessTimes(process.hProcess, &created, &exited, &kernel, &user))
    *o.cpuSeconds = seconds(kernel) + seconds(user);
  CloseHandle(process.hThread);
  CloseHandle(process.hProcess);
  if (job) CloseHandle(job);
  return int(code);
}

void reapFinishedProcesses() {}

bool openWithDesktop(const std::string& path) {
  const auto result =
      reinterpret_cast<INT_PTR>(ShellExecuteW(nullptr, L"open", widen(path).c_str(), nullptr, nullptr, SW_SHOWNORMAL));
  return result > 32;  // ShellExecute's documented success threshold
}
#else
namespace {

// With a memory limit: fork, set RLIMIT_AS in the child, exec (posix_spawn cannot set limits).
// Only async-signal-safe calls between fork and exec; everything they use is prepared before.
pid_t forkWithLimit(char* const* argv, char* const* envp, const ProcessOptions& o) {
  const rlim_t bytes = rlim_t(o.memoryLimitMb) << 20;
  const struct rlimit limit { bytes, bytes };
  const pid_t pid = fork();
  if (pid != 0) return pid;  // the parent (or -1)
  // A process group of its own: what it starts and leaves running is killed with it (runProcess).
  if (setpgid(0, 0) != 0 || setrlimit(RLIMIT_AS, &limit) != 0) _exit(127);
  const int flags = O_WRONLY | O_CREAT | O_TRUNC;
  if (!o.stdoutPath.empty()) {
    const int fd = open(o.stdoutPath.c_str(), flags, 0644);
    if (fd < 0 || dup2(fd, 1) < 0) _exit(127);
  }
  if (!o.stderrPath.empty()) {
    const int fd = open(o.stderrPath.c_str(), flags, 0644);
    if (fd < 0 || dup2(fd, 2) < 0) _exit(127);
  } else if (!o.stdoutPath.empty() && dup2(1, 2) < 0) _exit(127);
  execve(argv[0], argv, envp);
  _exit(127);
}

pid_t spawn(char* const* argv, char* const* envp, const ProcessOptions& o) {
  if (o.memoryLimitMb > 0) return forkWithLimit(argv, envp, o);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!o.stdoutPath.empty())
    posix_spawn_file_actions_addopen(&actions, 1, o.stdoutPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!o.stderrPath.empty())
    posix_spawn_file_actions_addopen(&actions, 2, o.stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  else if (!o.stdoutPath.empty()) posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv, envp) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Waits for `pid`; past o.timeoutSeconds (when set) it is killed with SIGKILL.
int waitFor(pid_t pid, const ProcessOptions& o, struct rusage& usage) {
  int status = 0;
  if (o.timeoutSeconds <= 0) {
    wait4(pid, &status, 0, &usage);
    return status;
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(o.timeoutSeconds);
  while (wait4(pid, &status, WNOHANG, &usage) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &usage);
      if (o.timedOut) *o.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status;
}

}  // namespace

int runProcess(const std::vector<std::string>& args, const ProcessOptions& o) {
  if (args.empty()) return -1;
  if (o.timedOut) *o.timedOut = false;
  std::vector<std::string> env = childEnvironment(currentEnvironment(), o);
  std::vector<char*> argv, envp;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  const pid_t pid = spawn(argv.data(), envp.data(), o);
  if (pid < 0) return -1;
  if (!o.wait) return 0;
  struct rusage usage {};
  const int status = waitFor(pid, o, usage);
  // Untrusted code (limited): whatever it started and left running in its group goes with it, as a
  // job object's processes do on Windows.
  if (o.memoryLimitMb > 0) kill(-pid, SIGKILL);
  if (o.cpuSeconds)
    *o.cpuSeconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                    1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  return WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
}

void reapFinishedProcesses() {
  while (waitpid(-1, nullptr, WNOHANG) > 0) {}
}

bool openWithDesktop(const std::string& path) {
#ifdef __APPLE__
  const char* viewer = "open";
#else
  const char* viewer = "xdg-open";
#endif
  std::vector<char*> argv = {const_cast<char*>(viewer), const_cast<char*>(path.c_str()), nullptr};
  pid_t pid = 0;
  return posix_spawnp(&pid, viewer, nullptr, nullptr, argv.data(), environ) == 0;
}
#endif

int checkProgramArgument(const char* tool, int argc, char** argv, const char* usage) {
  const std::string program = argc > 1 ? argv[1] : "";
  if (program == "--help" || program == "-h") {
    std::cout << usage;
    return 0;
  }
  std::error_code error;
  if (program.empty() || !std::filesystem::is_regular_file(program, error)) {
    if (!program.empty()) std::cerr << tool << ": no program at '" << program << "'\n";
    std::cerr << usage;
    return 2;
  }
  return -1;
}

}  // namespace shadowlab
