#include "support/paths.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace ussnav::test {

std::filesystem::path sharedData() { return USSNAV_SHARED_DATA_DIR; }

bool haveSharedData() { return std::filesystem::exists(sharedData() / "README.md"); }

std::string cliPath() { return USSNAV_CLI_PATH; }

int runCommand(const std::string& cmd, std::string* output) {
  FILE* p = ::popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return -1;
  std::array<char, 4096> buf{};
  std::string out;
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  const int st = ::pclose(p);
  if (output) *output = out;
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

namespace {
// Folders handed out by tempDir(); removed when the test process exits (each CTest test is its
// own process), unless USSNAV_KEEP_TEST_FILES is set for debugging.
struct TempDirs {
  std::vector<std::filesystem::path> dirs;
  ~TempDirs() {
    if (std::getenv("USSNAV_KEEP_TEST_FILES")) return;
    std::error_code ec;
    for (const auto& d : dirs) std::filesystem::remove_all(d, ec);
  }
};
TempDirs& tempDirs() {
  static TempDirs t;
  return t;
}
}  // namespace

std::filesystem::path tempDir(const std::string& name) {
  auto d = std::filesystem::temp_directory_path() /
           ("ussnav_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  tempDirs().dirs.push_back(d);
  return d;
}

}  // namespace ussnav::test
