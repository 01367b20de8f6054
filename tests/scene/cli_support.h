// Helpers for the scene tests: running the real `particles` binary and
// writing scene files to a private temporary directory.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace particles::test {

struct CliResult {
  int status = -1;  // exit status, or -1 if the program did not exit normally
  std::string out;  // stdout
  std::string err;  // stderr
};

inline std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q += "'\\''";
    else
      q += c;
  }
  return q + "'";
}

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

// A fresh directory of this process's own, removed with the object.
class TempDir {
 public:
  TempDir()
      : path_(std::filesystem::temp_directory_path() /
              ("particles-scene-tests-" + std::to_string(::getpid()) + "-" +
               std::to_string(counter()++))) {
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path file(const std::string& name) const { return path_ / name; }
  // Writes `text` to `name` and returns the file's path as a string.
  std::string write(const std::string& name, const std::string& text) const {
    writeFile(file(name), text);
    return file(name).string();
  }

 private:
  static int& counter() {
    static int n = 0;
    return n;
  }
  std::filesystem::path path_;
};

// Runs `particles ARGS` (args already shell-quoted as needed), capturing
// stdout and stderr separately.
inline CliResult runCli(const std::string& args) {
  static const TempDir scratch;
  static int calls = 0;
  const std::filesystem::path errFile = scratch.file("stderr-" + std::to_string(calls++) + ".txt");
  const std::string command =
      shellQuote(PARTICLES_CLI) + " " + args + " 2>" + shellQuote(errFile.string());
  CliResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  char buf[4096];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) result.out.append(buf, n);
  const int status = ::pclose(pipe);
  if (WIFEXITED(status)) result.status = WEXITSTATUS(status);
  result.err = readFile(errFile);
  return result;
}

inline std::string sceneFile(const std::string& name) {
  return (std::filesystem::path(PARTICLES_SCENES_DIR) / name).string();
}

}  // namespace particles::test
