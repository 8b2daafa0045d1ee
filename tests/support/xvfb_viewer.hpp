#pragma once
// `stipple view` as a child process in its own Xvfb server, driven with xdotool: what the viewer tests
// (test_cli_view*.cpp) share.
#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "support/test_paths.hpp"

namespace stipple::test {

// "" when Xvfb and xdotool are installed; otherwise what the test says when it skips.
std::string missing_viewer_tools();

// Polls `condition` every 100 ms until it holds or `timeout` passes; its last answer.
bool wait_for(const std::function<bool()>& condition, std::chrono::milliseconds timeout);

// How many times `what` occurs in `text`.
size_t count_of(const std::string& text, const std::string& what);

// A child process with its own environment additions and output files, killed if the test ends early.
class Child {
public:
    Child(const std::vector<std::string>& argv, const std::vector<std::pair<std::string, std::string>>& env,
          const std::filesystem::path& out, const std::filesystem::path& err);
    ~Child();
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;
    bool running();
    // Exit code after waiting up to `timeout`; -1 if it is still running (then it is killed).
    int wait_exit(std::chrono::seconds timeout);
    void terminate();

private:
    pid_t pid_ = -1;
    bool exited_ = false;
    int status_ = 0;
};

// An Xvfb server and the viewer in it, their output in files under `dir`.
class ViewerSession {
public:
    explicit ViewerSession(const std::filesystem::path& dir) : dir_(dir) {}

    // An unused display number: no socket and no lock file. Tests that ctest may run at the same time
    // start from different numbers, so they never race for one.
    bool start_x(int first_display = 87);
    void start_viewer(const std::vector<std::string>& args,
                      const std::vector<std::pair<std::string, std::string>>& extra_env = {});
    std::string xdotool(const std::string& args);

    std::string out() const { return slurp(dir_ / "view.out"); }
    std::string err() const { return slurp(dir_ / "view.err"); }
    Child& viewer() { return *viewer_; }

    // Keys reach the focused window; without a window manager the test gives the focus itself.
    void focus();
    bool find_window();
    const std::string& window() const { return window_; }
    const std::string& display() const { return display_; }

    // Presses S and waits for the viewer to report the PNG it wrote.
    std::string screenshot();

private:
    std::filesystem::path dir_;
    std::string display_;
    std::string window_;
    std::unique_ptr<Child> xvfb_;   // declared first: destroyed last
    std::unique_ptr<Child> viewer_;
};

}  // namespace stipple::test
