#pragma once
// The bench's plot-order row, measured here because it needs the export and the frame capture,
// which the bench library (below them in the layering) may not reach.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include "bench/plot_order_row.hpp"

namespace stipple::cli {

// Orders about `dots` blue-noise dots; with `bunny_view`, also captures the visible stipples of the
// bunny (models_dir/stanford-bunny.obj, default parameters and camera, width x height) and plans its
// plot. Without the scan the bunny's figure is left out with a note. Logs one line per figure.
bench::PlotOrderRow measure_plot_order_row(size_t dots, bool bunny_view, const std::filesystem::path& models_dir,
                                           uint32_t width, uint32_t height, int device,
                                           const std::function<void(const std::string&)>& log);

}  // namespace stipple::cli
