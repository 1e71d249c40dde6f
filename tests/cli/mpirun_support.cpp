// Running voxmod under mpirun in the CLI tests (mpirun_support.h).
#include "cli/mpirun_support.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace vox::test {

RunResult runProgram(const std::vector<std::string>& args, const std::map<std::string, std::string>& env) {
  TempDir tmp;
  const auto out_path = tmp / "stdout", err_path = tmp / "stderr";
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
    std::vector<std::string> copy = args;
    std::vector<char*> argv;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (!freopen(out_path.c_str(), "w", stdout) || !freopen(err_path.c_str(), "w", stderr)) _exit(126);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = readFile(out_path);
  r.err = readFile(err_path);
  return r;
}

std::vector<std::string> mpirunArgs(int ranks) {
  std::vector<std::string> args = {"mpirun", "--oversubscribe", "-np", std::to_string(ranks)};
  if (geteuid() == 0) args.push_back("--allow-run-as-root");
  args.push_back(voxmodExecutable());
  return args;
}

std::string mpiMissing() {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) return "mpirun not found (openmpi-bin)";
  TempDir tmp;
  std::vector<std::string> args = mpirunArgs(2);
  for (const char* a : {"batch", "no-such-input.stl", "-o"}) args.push_back(a);
  args.push_back((tmp / "out").string());
  args.push_back("--format=vxm");
  if (runProgram(args).err.find("built without MPI") != std::string::npos) return "voxmod is built without MPI";
  return {};
}

}  // namespace vox::test
