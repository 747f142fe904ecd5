#pragma once
// Runs the cellsim executable as a user would, capturing exit code and stderr.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cellsim::testing {

struct CliResult {
  int exit_code;
  std::string err, out;  // stderr and stdout
};

// A fresh scratch directory per test, removed at the end.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("cellsim-test-" + name + "-" + std::to_string(::getpid()))) {
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

inline CliResult run_cli(const std::string& args, const ScratchDir& dir) {
  const std::string err_file = dir.file("stderr.txt"), out_file = dir.file("stdout.txt");
  const std::string cmd = std::string(CELLSIM_EXE) + " " + args + " > " + out_file + " 2> " + err_file;
  const int status = std::system(cmd.c_str());
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
