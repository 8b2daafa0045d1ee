#pragma once
// `stipple view --script FILE`: timed actions for reproducible demos and tests, one per line:
//   wait SECONDS               let the viewer run (drawing) for that long
//   wait-idle                  until the background work (new stipples, loads) is done and shown
//   set OBJECT KEY VALUE       a per-object parameter by its scene key (the parameter table's), as the
//                              panel would set it; generation parameters then make new stipples
//   screenshot PATH            a PNG of the next frame (window resolution, without the panel)
//   export PATH                the current view as .svg, .pdf or .csv (A4, 10 mm margin: render's defaults)
//   quit                       close the viewer (exit code 0)
// Blank lines and lines starting with # are ignored. Errors name the file and the line.
#include <optional>
#include <string>
#include <vector>

namespace stipple::app {

struct ScriptAction {
    enum class Kind { Wait, WaitIdle, Set, Screenshot, Export, Quit };
    Kind kind;
    double seconds = 0.0;  // Wait
    size_t object = 0;     // Set
    std::string key;       // Set: the parameter's scene key
    double value = 0.0;    // Set: the value as the table keeps it
    std::string path;      // Screenshot, Export
    int line = 0;
};

// Reads and checks a script (keys and values against the parameter table); throws stipple::Error
// "<file>:<line>: <problem>".
std::vector<ScriptAction> read_viewer_script(const std::string& path);

}  // namespace stipple::app
