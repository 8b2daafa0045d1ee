#include "support/xvfb_viewer.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <thread>

namespace stipple::test {

using namespace std::chrono_literals;

namespace {

bool have_tool(const std::string& name) { return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0; }

}  // namespace

std::string missing_viewer_tools() {
    for (const char* tool : {"Xvfb", "xdotool"})
        if (!have_tool(tool))
            return std::string(tool) + " is not installed (apt-get install xvfb xdotool); viewer not tested";
    return "";
}

bool wait_for(const std::function<bool()>& condition, std::chrono::milliseconds timeout) {
    auto end = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < end) {
        if (condition()) return true;
        std::this_thread::sleep_for(100ms);
    }
    return condition();
}

size_t count_of(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

Child::Child(const std::vector<std::string>& argv, const std::vector<std::pair<std::string, std::string>>& env,
             const std::filesystem::path& out, const std::filesystem::path& err) {
    pid_ = fork();
    if (pid_ == 0) {
        for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
        int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int n = open("/dev/null", O_RDONLY);
        dup2(n, 0), dup2(o, 1), dup2(e, 2);
        std::vector<char*> args;
        for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execvp(args[0], args.data());
        _exit(127);
    }
}

Child::~Child() {
    if (!running()) return;
    // SIGTERM first, so that Xvfb removes its socket and lock file; SIGKILL if it lingers.
    kill(pid_, SIGTERM);
    for (int i = 0; i < 40 && running(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (running()) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
    }
}

bool Child::running() {
    if (pid_ <= 0 || exited_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        status_ = status;
    }
    return !exited_;
}

int Child::wait_exit(std::chrono::seconds timeout) {
    auto end = std::chrono::steady_clock::now() + timeout;
    while (running() && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(50ms);
    if (running()) return -1;
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
}

void Child::terminate() {
    if (running()) kill(pid_, SIGTERM);
}

bool ViewerSession::start_x(int first_display) {
    for (int n = first_display; n < first_display + 100; ++n) {
        if (std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(n)) ||
            std::filesystem::exists("/tmp/.X" + std::to_string(n) + "-lock"))
            continue;
        display_ = ":" + std::to_string(n);
        xvfb_ = std::make_unique<Child>(
            // -noreset: otherwise the server resets when its last client (the readiness probe below)
            // disconnects, and a viewer connecting during the reset fails to open the display.
            std::vector<std::string>{"Xvfb", display_, "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
                                     "-noreset"},
            std::vector<std::pair<std::string, std::string>>{}, dir_ / "xvfb.out", dir_ / "xvfb.err");
        if (wait_for([&] { return xdotool("getmouselocation").find("x:") != std::string::npos; }, 10s)) return true;
        xvfb_.reset();
    }
    return false;
}

void ViewerSession::start_viewer(const std::vector<std::string>& args,
                                 const std::vector<std::pair<std::string, std::string>>& extra_env) {
    std::vector<std::pair<std::string, std::string>> env{{"DISPLAY", display_}, {"STIPPLE_VALIDATION", "1"}};
    env.insert(env.end(), extra_env.begin(), extra_env.end());
    if (!std::getenv("XDG_RUNTIME_DIR")) {
        std::filesystem::create_directories(dir_ / "xdg");
        chmod((dir_ / "xdg").c_str(), 0700);
        env.push_back({"XDG_RUNTIME_DIR", (dir_ / "xdg").string()});
    }
    std::vector<std::string> argv{STIPPLE_EXECUTABLE, "view"};
    argv.insert(argv.end(), args.begin(), args.end());
    viewer_ = std::make_unique<Child>(argv, env, dir_ / "view.out", dir_ / "view.err");
}

std::string ViewerSession::xdotool(const std::string& args) {
    std::string cmd = "DISPLAY=" + display_ + " xdotool " + args + " 2>/dev/null";
    std::string out;
    if (FILE* p = popen(cmd.c_str(), "r")) {
        char buffer[256];
        while (fgets(buffer, sizeof(buffer), p)) out += buffer;
        pclose(p);
    }
    return out;
}

void ViewerSession::focus() {
    xdotool("windowfocus " + window_ + " mousemove --window " + window_ + " 900 500");
    std::this_thread::sleep_for(200ms);
}

bool ViewerSession::find_window() {
    return wait_for(
               [&] {
                   std::string found = xdotool("search --name '^stipple - '");
                   window_ = found.substr(0, found.find('\n'));
                   return !window_.empty() || !viewer_->running();
               },
               40s) &&
           !window_.empty();
}

std::string ViewerSession::screenshot() {
    size_t before = count_of(out(), "screenshot: ");
    xdotool("key s");
    if (!wait_for([&] { return count_of(out(), "screenshot: ") > before; }, 20s)) return "";
    std::string text = out();
    size_t at = text.rfind("screenshot: ") + 12;
    return text.substr(at, text.find('\n', at) - at);
}

}  // namespace stipple::test
