#pragma once
// Shared by the test_export_* suites: error checks and small drawings with known content.
// Header-only: only the export tests (which link stipple_export) include it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "export/drawing.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple::test {

// Checks that `fn` throws stipple::Error whose single-line message contains `needle`.
template <class Fn>
void expect_plot_error(Fn&& fn, const std::string& needle) {
    try {
        fn();
        ADD_FAILURE() << "expected stipple::Error containing '" << needle << "'";
    } catch (const stipple::Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(needle), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << "error must be one line: " << what;
    }
}

// A write that fails part way (a full disk; here the file-size limit) must leave the file that was there and
// no part of the new one. `write(path, large)`: a writer of `small` and `large` plans (PDF, SVG, CSV); the
// failure's message must contain `needle` after the path.
template <class Plan, class Write>
void expect_failed_write_keeps_the_file(const std::string& folder, const std::string& name, const Plan& small,
                                        const Plan& large, Write&& write, const std::string& needle) {
    const auto dir = temp_dir(folder);
    const std::string path = (dir / name).string();
    write(path, small);
    const auto read_bytes = [](const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string good = read_bytes(path);
    {
        ScopedFileSizeLimit limit(good.size() + 100);
        expect_plot_error([&] { write(path, large); }, path + ": " + needle);
    }
    EXPECT_EQ(read_bytes(path), good);
    EXPECT_EQ(folder_entries(dir.string()), std::vector<std::string>{name});
}

// A 400x300 px drawing with one object "cube" holding `dots` dots on a grid (intensity 1,
// radius 1.5 px) and a square outline 100 px wide given as four contour segments, drawn 2 px wide.
inline plot::Drawing grid_drawing(int dots_x = 10, int dots_y = 10) {
    plot::Drawing d;
    d.width_px = 400;
    d.height_px = 300;
    d.objects.push_back({"cube", 2.0f});
    for (int y = 0; y < dots_y; ++y)
        for (int x = 0; x < dots_x; ++x)
            d.dots.push_back({glm::vec2(50.0f + 20.0f * x, 50.0f + 20.0f * y), 1.5f, 1.0f, 0, static_cast<uint32_t>(y * dots_x + x)});
    const glm::vec2 c[4] = {{250, 100}, {350, 100}, {350, 200}, {250, 200}};
    for (int i = 0; i < 4; ++i) d.segments.push_back({c[i], c[(i + 1) % 4], 0, plot::LineKind::Contour});
    return d;
}

// Whether a command-line tool (rsvg-convert, pdftoppm, pdfinfo) is installed.
inline bool have_tool(const std::string& name) { return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0; }

// Runs a shell command line; its exit status.
inline int run_shell(const std::string& command) { return std::system(command.c_str()); }

inline std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

}  // namespace stipple::test
