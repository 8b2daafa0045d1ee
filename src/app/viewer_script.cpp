#include "app/viewer_script.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/decimal.hpp"
#include "core/error.hpp"
#include "export/plot_file.hpp"
#include "params/param_table.hpp"

namespace stipple::app {

namespace {

double parse_number(const std::string& text, bool* ok) {
    const std::optional<double> value = parse_decimal(text);
    *ok = value.has_value();
    return value.value_or(0.0);
}

// A piece of the script quoted in a message: one line, and short (a 20 MB line was quoted whole).
std::string script_text(const std::string& text) { return quoted_excerpt(text, 80); }

// Object numbers beyond any scene's (a double that size_t cannot hold converted to object 0).
constexpr double kMostObjects = 1e9;

}  // namespace

std::vector<ScriptAction> read_viewer_script(const std::string& path) {
    // A folder opens as an empty stream (an empty script: the window never closed), a FIFO waits.
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(status)) fail_file(path, "is a directory, not a script");
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) fail_file(path, "is not a regular file");
    std::ifstream in(path);
    if (!in) fail_file(path, "cannot open the script (missing or unreadable)");
    std::vector<ScriptAction> actions;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        std::string verb;
        if (!(words >> verb) || verb[0] == '#') continue;
        const std::string where = path + ":" + std::to_string(number);
        auto bad = [&](const std::string& problem) { fail(where + ": " + problem); };
        ScriptAction action{};
        action.line = number;
        std::vector<std::string> rest;
        for (std::string w; words >> w;) rest.push_back(w);
        bool ok = false;
        if (verb == "wait" && rest.size() == 1) {
            action.kind = ScriptAction::Kind::Wait;
            action.seconds = parse_number(rest[0], &ok);
            if (!ok || action.seconds < 0.0 || action.seconds > 3600.0) bad("wait needs seconds in 0..3600");
        } else if (verb == "wait-idle" && rest.empty()) {
            action.kind = ScriptAction::Kind::WaitIdle;
        } else if (verb == "set" && rest.size() == 3) {
            action.kind = ScriptAction::Kind::Set;
            const double object = parse_number(rest[0], &ok);
            if (!ok || object < 0.0 || object != std::floor(object) || object > kMostObjects)
                bad("set needs an object number, got " + script_text(rest[0]));
            action.object = size_t(object);
            const ParamSpec* spec = find_param(rest[1]);
            if (!spec) bad(script_text(rest[1]) + " is not a parameter (the keys are the scene file's: stipple params --markdown lists them)");
            action.key = rest[1];
            if (spec->type == ParamType::Bool) {
                if (rest[2] != "true" && rest[2] != "false") bad(action.key + ": expected true or false, got " + script_text(rest[2]));
                action.value = rest[2] == "true" ? 1.0 : 0.0;
            } else {
                try {
                    action.value = parse_param_text(*spec, rest[2], true);  // named as the script names it
                } catch (const Error& e) {
                    bad(excerpt(e.what(), 200));  // it quotes the value whole
                }
            }
        } else if (verb == "screenshot" && rest.size() == 1) {
            action.kind = ScriptAction::Kind::Screenshot;
            action.path = rest[0];
            if (!plot::is_png_path(action.path)) bad("screenshot needs a .png path, got " + script_text(action.path));
        } else if (verb == "export" && rest.size() == 1) {
            action.kind = ScriptAction::Kind::Export;
            action.path = rest[0];
            if (!plot::is_plot_path(action.path)) bad("export needs a .svg, .pdf or .csv path, got " + script_text(action.path));
        } else if (verb == "quit" && rest.empty()) {
            action.kind = ScriptAction::Kind::Quit;
        } else {
            bad("unknown or incomplete line " + script_text(line) + " (wait S, wait-idle, set OBJECT KEY VALUE, screenshot PATH, export PATH, quit)");
        }
        actions.push_back(action);
    }
    // Nothing to do is a mistake (a wrong file, or one not yet written), not a script: the window would
    // stay open, waiting for a person, where a script was meant to drive it.
    if (actions.empty()) fail_file(path, "holds no action (wait S, wait-idle, set OBJECT KEY VALUE, screenshot PATH, export PATH, quit)");
    return actions;
}

}  // namespace stipple::app
