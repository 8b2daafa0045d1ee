#pragma once
// What `stipple bench` writes: the Markdown report (also printed), the JSON with every figure, and
// the chart (fps against polygon count, log-log, ours against the paper's) as hand-written SVG.
#include <string>

#include "bench/bench_runner.hpp"

namespace stipple::bench {

std::string markdown_report(const BenchResults& results);
// What the rows were made from where some or all scans are missing: "PROCEDURAL UV spheres ..." for every row,
// else the rows that are spheres (the others derived from the scans).
std::string models_note(const BenchResults& results);
std::string json_report(const BenchResults& results);  // pretty-printed
std::string svg_chart(const BenchResults& results);

// Writes `text` to `path` (creating folders); throws stipple::Error("<path>: ...") on failure.
void write_text_file(const std::string& path, const std::string& text);

// 1234567 -> "1,234,567".
std::string with_commas(uint64_t n);
// Frame rates with three significant figures or so: 1234 -> "1234", 85.23 -> "85.2", 4.651 -> "4.65".
std::string fps_text(double fps);

}  // namespace stipple::bench
