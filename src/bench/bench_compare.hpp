#pragma once
// The regression guard (issue 17): `stipple bench --compare OLD/results.json` sets this run's speeds
// beside an earlier run's and lists what got slower. Not a timed test: timings on a shared machine
// vary by ±20%, so the guard prints and leaves the judgement to whoever reads it.
//
// A speed is a figure where more is better, keyed by what it measures:
//   "<model> / <column>"          median fps of a cell (model x path x lines)
//   "<model> / generation"        stipple generation, candidates per second
//   "plot order / <what>"         dots ordered per second (the plot-order row)
#include <map>
#include <string>
#include <vector>

namespace stipple::bench {

// Cells that lost more than this share of their speed are reported as slower.
inline constexpr double kSlowerThreshold = 0.10;

struct SpeedChange {
    std::string key;
    double old_speed = 0.0, new_speed = 0.0;
    // The share of the old speed that was lost (0.25: a quarter slower; negative: faster).
    double loss() const { return old_speed > 0.0 ? 1.0 - new_speed / old_speed : 0.0; }
};

struct Comparison {
    std::vector<std::string> settings;        // how the runs were made differently ("width 640 -> 1280"), if at all
    std::vector<std::string> not_comparable;  // models drawn from other geometry ("horse: horse.ply, 96966
                                              // triangles -> procedural sphere, 98000 triangles"): left out
    size_t compared = 0;                   // keys in both runs
    std::vector<SpeedChange> slower;       // loss > threshold, worst first
    std::vector<std::string> only_in_old;  // keys the new run lacks
    std::vector<std::string> only_in_new;  // keys the old run lacks
    SpeedChange worst;                     // the largest loss among the compared keys (if any)
};

// The speeds of a results.json text, by key. Throws stipple::Error("<name>: ...") when the text is not
// JSON or not a bench results file (no "models" list, a cell without a number for its fps).
std::map<std::string, double> read_speeds(const std::string& json_text, const std::string& name);

Comparison compare_speeds(const std::map<std::string, double>& old_speeds, const std::map<std::string, double>& new_speeds,
                          double threshold = kSlowerThreshold);

// Reads `path` (a results.json); throws stipple::Error("<path>: ...") when missing, a folder, unreadable or
// malformed.
std::map<std::string, double> read_speeds_file(const std::string& path);
// The same, returning the file's text (checked as read_speeds_file checks it).
std::string read_results_file(const std::string& path);

// Two results.json texts (both accepted by read_speeds): compare_speeds over the models drawn from the same
// geometry in both, with the settings that differ between the runs (frame size, queued and timed frames,
// --quick, device, depth options) listed, since a speed measured otherwise is no regression.
Comparison compare_runs(const std::string& old_text, const std::string& old_name, const std::string& new_text,
                        double threshold = kSlowerThreshold);

// What the bench prints: the slower cells, the missing ones, then one summary line
// ("compared with OLD: N cells compared, K slower by more than 10%, the worst: KEY -23.4% (a -> b)").
std::string comparison_text(const Comparison& comparison, const std::string& old_name,
                            double threshold = kSlowerThreshold);

}  // namespace stipple::bench
