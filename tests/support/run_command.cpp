#include "support/run_command.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "support/test_paths.hpp"

namespace stipple::test {

namespace {

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

CommandResult run_stipple(const std::vector<std::string>& args, const std::string& shell_prefix) {
    static int counter = 0;
    std::filesystem::path dir = std::filesystem::temp_directory_path() / "stipple-cli-capture";
    std::filesystem::create_directories(dir);
    std::string stem = std::to_string(::getpid()) + "-" + std::to_string(counter++);
    std::filesystem::path out = dir / (stem + ".out"), err = dir / (stem + ".err");
    std::string cmd = (shell_prefix.empty() ? "" : shell_prefix + " ") + quote(STIPPLE_EXECUTABLE);
    for (const std::string& a : args) cmd += " " + quote(a);
    cmd += " >" + quote(out.string()) + " 2>" + quote(err.string()) + " </dev/null";
    int status = std::system(cmd.c_str());
    CommandResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    result.out = slurp(out);
    result.err = slurp(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return result;
}

std::vector<std::string> folder_entries(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace stipple::test
