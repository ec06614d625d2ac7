#pragma once
// Where tests find the third-party data (read in place, never copied) and the CLI binary.

#include <filesystem>
#include <string>

namespace ussnav::test {

// ../shared/data beside the repository (USSNAV_SHARED_DATA_DIR at configure time).
std::filesystem::path sharedData();
// Skips the calling test (GTEST_SKIP) is the caller's job when this returns false.
bool haveSharedData();
// Path of the built `ussnav` executable.
std::string cliPath();
// Runs a shell command, returns its exit status; stdout+stderr captured into `output`.
int runCommand(const std::string& cmd, std::string* output = nullptr);
// A fresh temporary folder unique to the calling test; removed when the test process exits
// (set USSNAV_KEEP_TEST_FILES=1 to keep it for debugging).
std::filesystem::path tempDir(const std::string& name);

}  // namespace ussnav::test
