#pragma once
// Runs the cellsim executable as a user would, capturing exit code, stdout and stderr. Arguments are
// passed as a list, without a shell, and every scratch directory's name contains a space, so each
// CLI test also checks that paths with spaces work.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cellsim::testing {

using Args = std::vector<std::string>;

struct CliResult {
  int exit_code;
  std::string err, out;  // stderr and stdout
};

// A fresh scratch directory per test ("cellsim test-NAME-PID" under TMPDIR), removed at the end.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("cellsim test-" + name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(file(name)) << text;
    return file(name);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline CliResult run_cli(const Args& args, const ScratchDir& dir) {
  const std::string err_file = dir.file("stderr.txt"), out_file = dir.file("stdout.txt");
  std::vector<std::string> argv_text = {CELLSIM_EXE};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t redirect;
  posix_spawn_file_actions_init(&redirect);
  posix_spawn_file_actions_addopen(&redirect, STDOUT_FILENO, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&redirect, STDERR_FILENO, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  int status = 0;
  const int spawned = posix_spawn(&pid, CELLSIM_EXE, &redirect, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&redirect);
  if (spawned != 0) return {127, "cannot start " + std::string(CELLSIM_EXE), ""};
  waitpid(pid, &status, 0);
  const auto contents = [](const std::string& file) {
    std::ifstream in(file);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return {code, contents(err_file), contents(out_file)};
}

}  // namespace cellsim::testing
