// The PDF (through cairo): the page in points, read back from the file, and, rasterised by
// pdftoppm, ink exactly where the dots and the outline are.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

#include "export/pdf_writer.hpp"
#include "export/plot_plan.hpp"
#include "io/png_io.hpp"
#include "support/export_helpers.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace {

using namespace stipple::plot;
using stipple::test::grid_drawing;

std::string read_all(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

// The first page's MediaBox width and height in points.
std::pair<double, double> media_box(const std::string& pdf) {
    std::smatch match;
    const std::regex box(R"(/MediaBox\s*\[\s*([-0-9.]+)\s+([-0-9.]+)\s+([-0-9.]+)\s+([-0-9.]+)\s*\])");
    if (!std::regex_search(pdf, match, box)) return {0.0, 0.0};
    return {std::stod(match[3]) - std::stod(match[1]), std::stod(match[4]) - std::stod(match[2])};
}

TEST(ExportPdf, PageSizeInPoints) {
    const auto dir = stipple::test::temp_dir("export_pdf_size");
    struct Case { const char* page; double width_pt, height_pt; };
    for (const Case& c : {Case{"A4-portrait", 595.276, 841.89}, Case{"A3-landscape", 1190.55, 841.89}, Case{"100x50mm", 283.465, 141.732}, Case{"letter", 792.0, 612.0} /* bare: turned as the 400 x 300 drawing */}) {
        ExportOptions options;
        options.page = parse_page(c.page);
        const auto path = dir / (std::string(c.page) + ".pdf");
        write_pdf(make_plot_plan(grid_drawing(), options), path.string());
        const std::string pdf = read_all(path);
        ASSERT_EQ(pdf.rfind("%PDF-", 0), 0u) << c.page;
        const auto [width, height] = media_box(pdf);
        EXPECT_NEAR(width, c.width_pt, 0.01) << c.page;
        EXPECT_NEAR(height, c.height_pt, 0.01) << c.page;
    }
    if (!stipple::test::have_tool("pdfinfo")) GTEST_SKIP() << "pdfinfo (poppler-utils) not installed: MediaBox checked, pdfinfo not";
    ASSERT_EQ(stipple::test::run_shell("pdfinfo " + stipple::test::quoted(dir / "A4-portrait.pdf") + " > " + stipple::test::quoted(dir / "info.txt")), 0);
    const std::string info = read_all(dir / "info.txt");
    EXPECT_TRUE(std::regex_search(info, std::regex(R"(Pages:\s+1\n)"))) << info;
    EXPECT_NE(info.find("595.276 x 841.89 pts (A4)"), std::string::npos) << info;
}

// With SOURCE_DATE_EPOCH (the reproducible-builds convention) the same plan writes the same bytes: cairo
// otherwise dates the file to the second it was written.
TEST(ExportPdf, SourceDateEpochMakesTheSameBytes) {
    const auto dir = stipple::test::temp_dir("export_pdf_date");
    ASSERT_EQ(setenv("SOURCE_DATE_EPOCH", "1764900000", 1), 0);
    write_pdf(make_plot_plan(grid_drawing(), {}), (dir / "a.pdf").string());
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    write_pdf(make_plot_plan(grid_drawing(), {}), (dir / "b.pdf").string());
    unsetenv("SOURCE_DATE_EPOCH");
    const std::string a = read_all(dir / "a.pdf");
    EXPECT_EQ(a, read_all(dir / "b.pdf"));
    EXPECT_NE(a.find("/CreationDate (20251205020000Z)"), std::string::npos) << "2025-12-05 02:00 UTC";
}

TEST(ExportPdf, LayersAreGroups) {
    const auto dir = stipple::test::temp_dir("export_pdf_groups");
    Drawing drawing = grid_drawing();
    drawing.objects.push_back({"second", 1.0f});
    drawing.dots.push_back({glm::vec2(20.0f, 20.0f), 1.0f, 1.0f, 1, 0});
    write_pdf(make_plot_plan(drawing, {}), (dir / "groups.pdf").string());
    const std::string pdf = read_all(dir / "groups.pdf");
    size_t groups = 0;
    for (size_t at = pdf.find("/Subtype /Form"); at != std::string::npos; at = pdf.find("/Subtype /Form", at + 1)) ++groups;
    EXPECT_EQ(groups, 3u);  // cube stipples, cube lines, second stipples
}

TEST(ExportPdf, RasterisedInkIsWhereTheDrawingIs) {
    if (!stipple::test::have_tool("pdftoppm")) GTEST_SKIP() << "pdftoppm (poppler-utils) not installed";
    Drawing drawing = grid_drawing(10, 10);
    for (Dot& dot : drawing.dots) dot.radius_px = 4.0f;
    ExportOptions options;
    options.page = parse_page("400x300mm");
    options.margin_mm = 0.0;  // 1 mm per pixel
    options.fit = Fit::Frame;
    options.pen_width_mm = 2.0;
    options.fill_paper = true;
    const auto dir = stipple::test::temp_dir("export_pdf_raster");
    write_pdf(make_plot_plan(drawing, options), (dir / "drawing.pdf").string());
    // 25.4 dpi: one pixel per millimetre.
    ASSERT_EQ(stipple::test::run_shell("pdftoppm -png -r 25.4 -singlefile " + stipple::test::quoted(dir / "drawing.pdf") + " " +
                                       stipple::test::quoted(dir / "drawing")),
              0);
    const stipple::Image image = stipple::read_png((dir / "drawing.png").string());
    ASSERT_NEAR(image.width, 400, 1);
    for (const Dot& dot : drawing.dots) {
        EXPECT_LT(stipple::luminance(image, int(dot.px.x), int(dot.px.y)), 60) << dot.px.x << "," << dot.px.y;
        EXPECT_GT(stipple::luminance(image, int(dot.px.x) + 10, int(dot.px.y) + 10), 200);
    }
    // The square outline (250..350 x 100..200): inked on its edges, paper inside.
    EXPECT_LT(stipple::luminance(image, 300, 100), 100);
    EXPECT_LT(stipple::luminance(image, 350, 150), 100);
    EXPECT_GT(stipple::luminance(image, 300, 150), 200);
}

// An object with an ink of its own draws its layers in it, the others in the drawing's (rasterised by pdftoppm).
TEST(ExportPdf, EachObjectsLayersTakeItsInk) {
    if (!stipple::test::have_tool("pdftoppm")) GTEST_SKIP() << "pdftoppm (poppler-utils) not installed";
    Drawing drawing = grid_drawing(10, 10);
    for (Dot& dot : drawing.dots) dot.radius_px = 4.0f;
    drawing.objects.push_back({"ball", 2.0f});
    const glm::vec2 ball(320.0f, 260.0f);
    drawing.dots.push_back({ball, 6.0f, 1.0f, 1, 0});
    drawing.ink = glm::vec3(0.0f, 0.0f, 1.0f);
    drawing.objects[0].ink = glm::vec3(1.0f, 0.0f, 0.0f);
    ExportOptions options;
    options.page = parse_page("400x300mm");
    options.margin_mm = 0.0;  // 1 mm per pixel
    options.fit = Fit::Frame;
    options.pen_width_mm = 2.0;
    const auto dir = stipple::test::temp_dir("export_pdf_inks");
    write_pdf(make_plot_plan(drawing, options), (dir / "drawing.pdf").string());
    ASSERT_EQ(stipple::test::run_shell("pdftoppm -png -r 25.4 -singlefile " + stipple::test::quoted(dir / "drawing.pdf") + " " +
                                       stipple::test::quoted(dir / "drawing")),
              0);
    const stipple::Image image = stipple::read_png((dir / "drawing.png").string());
    const auto rgb = [&](int x, int y) {
        const uint8_t* p = &image.pixels[size_t(image.channels) * (size_t(y) * image.width + x)];
        return glm::ivec3(p[0], p[1], p[2]);
    };
    for (const Dot& dot : drawing.dots) {
        const glm::ivec3 c = rgb(int(dot.px.x), int(dot.px.y));
        const bool own = dot.object == 0;
        EXPECT_GT(own ? c.r : c.b, 200) << dot.px.x << "," << dot.px.y;
        EXPECT_LT(own ? c.b : c.r, 60) << dot.px.x << "," << dot.px.y;
        EXPECT_LT(c.g, 60) << dot.px.x << "," << dot.px.y;
    }
    const glm::ivec3 outline = rgb(300, 100);  // the first object's square outline
    EXPECT_GT(outline.r, 200);
    EXPECT_LT(outline.b, 100);
}

TEST(ExportPdf, UnwritablePathIsOneLineError) {
    const PlotPlan plan = make_plot_plan(grid_drawing(2, 2), {});
    // Under a file, where no folder can be made (a missing folder is made: root could make /nonexistent-dir).
    const auto dir = stipple::test::temp_dir("export_pdf_unwritable");
    const std::string file = (dir / "file").string();
    std::ofstream(file) << "a file";
    stipple::test::expect_plot_error([&] { write_pdf(plan, file + "/x.pdf"); }, file + "/x.pdf: cannot write PDF");
}

// A write that fails part way (a full disk; here the file-size limit) leaves the file that was there, and no
// part of the new one: it had left a truncated PDF in place of the good one.
TEST(ExportPdf, AFailedWriteLeavesTheFileThatWasThere) {
    stipple::test::expect_failed_write_keeps_the_file(
        "export_pdf_failed_write", "x.pdf", make_plot_plan(grid_drawing(2, 2), {}), make_plot_plan(grid_drawing(200, 200), {}),
        [](const std::string& path, const PlotPlan& plan) { write_pdf(plan, path); }, "cannot write PDF: File too large");
}

}  // namespace
