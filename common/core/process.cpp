#include "core/process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

extern char** environ;

namespace shadowlab {

int runProcess(const std::vector<std::string>& args, const ProcessOptions& o) {
  if (args.empty()) return -1;
  std::vector<std::string> env;
  auto named = [](const std::string& entry, const std::string& name) { return entry.rfind(name + "=", 0) == 0; };
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    bool drop =
        std::any_of(o.unsetEnv.begin(), o.unsetEnv.end(), [&](const std::string& n) { return named(entry, n); });
    for (const auto& s : o.setEnv) drop = drop || named(entry, s.substr(0, s.find('=')));
    if (!drop) env.push_back(entry);
  }
  env.insert(env.end(), o.setEnv.begin(), o.setEnv.end());

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!o.stdoutPath.empty())
    posix_spawn_file_actions_addopen(&actions, 1, o.stdoutPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!o.stderrPath.empty())
    posix_spawn_file_actions_addopen(&actions, 2, o.stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  else if (!o.stdoutPath.empty()) posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::vector<char*> argv, envp;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  for (auto& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid;
  int status = 0;
  const bool started = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()) == 0;
  posix_spawn_file_actions_destroy(&actions);
  if (!started) return -1;
  struct rusage usage {};
  wait4(pid, &status, 0, &usage);
  if (o.cpuSeconds)
    *o.cpuSeconds = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                    1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  return WIFEXITED(status) ? WEXITSTATUS(status) : WIFSIGNALED(status) ? 128 + WTERMSIG(status) : -1;
}

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
