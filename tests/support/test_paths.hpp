#pragma once
// Where tests find the shared real models and where they write their output.
#include <filesystem>
#include <string>

namespace stipple::test {

// ../shared/models/<name>, or "" when absent (the caller then GTEST_SKIPs with a message).
std::string shared_model(const std::string& name);
// <source>/<relative>: the project's own files (assets, golden images, the README).
std::string source_path(const std::string& relative);
// The whole text of a file ("" when it cannot be read).
std::string slurp(const std::filesystem::path& path);
// <build>/test-output/<name>, creating the folder.
std::filesystem::path output_path(const std::string& name);
// A fresh empty temporary folder for files a test writes itself: <build>/test-output/tmp/<test_name>.
std::filesystem::path temp_dir(const std::string& test_name);

}  // namespace stipple::test
