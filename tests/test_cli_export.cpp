// Vector output is the PNG (issue 15): `stipple render -o x.svg|x.pdf|x.csv` writes the stipples the
// frame actually draws. Rasterised (rsvg-convert, pdftoppm) at the PNG's size, the SVG and the PDF carry
// the PNG's ink inside the object; the SVG's dot centres lie on inked pixels of the PNG; the files are
// valid (layers, a mm page, the PDF's page in points); a hidden object contributes no dot.
//
// Rasterisers cover tiny shapes imperfectly (a 1.7-px disc comes out up to 30% light at 1x in poppler),
// so the vector files are rasterised at 8x and the mean ink compared: the mean over a finer grid is the
// true coverage, which the screen image's pixels hold exactly.
#include <gtest/gtest.h>

#include <tinyxml2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/png_io.hpp"
#include "support/model_files.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

constexpr int kWidth = 640, kHeight = 512, kSuper = 8;

bool have_tool(const std::string& name) { return std::system(("command -v " + name + " >/dev/null 2>&1").c_str()) == 0; }

// Runs stipple; returns what it printed.
std::string run_ok(const std::vector<std::string>& args) {
    const test::CommandResult r = test::run_stipple(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.out;
}

void shell_ok(const std::string& command) { ASSERT_EQ(std::system(command.c_str()), 0) << command; }

double darkness(const Image& image, int x, int y) {
    const uint8_t* p = &image.pixels[(size_t(y) * image.width + x) * image.channels];
    if (image.channels < 3) return 1.0 - p[0] / 255.0;  // grey (and alpha): a rasteriser's PNG may be
    return 1.0 - (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255.0;
}

// Mean ink of `image` (any multiple of the mask's size) over the pixels the mask marks covered.
double mean_ink_inside(const Image& image, const Image& mask) {
    const int k = image.width / mask.width;
    // A rasteriser may round the page up by a row or a column: only pixels over the mask count.
    const int height = std::min(image.height, mask.height * k), width = std::min(image.width, mask.width * k);
    double sum = 0.0;
    size_t n = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (darkness(mask, x / k, y / k) > 0.5) continue;  // the mask is white where a surface covers
            sum += darkness(image, x, y);
            ++n;
        }
    return n ? sum / double(n) : 0.0;
}

struct Svg {
    std::string width, height, view_box;
    std::vector<std::string> layers;
    std::vector<std::pair<double, double>> dots;  // centres in mm
};

Svg read_svg(const std::string& path) {
    tinyxml2::XMLDocument doc;
    EXPECT_EQ(doc.LoadFile(path.c_str()), tinyxml2::XML_SUCCESS) << path << " is not XML";
    Svg svg;
    const tinyxml2::XMLElement* root = doc.RootElement();
    if (!root) return svg;
    svg.width = root->Attribute("width") ? root->Attribute("width") : "";
    svg.height = root->Attribute("height") ? root->Attribute("height") : "";
    svg.view_box = root->Attribute("viewBox") ? root->Attribute("viewBox") : "";
    for (const tinyxml2::XMLElement* g = root->FirstChildElement("g"); g; g = g->NextSiblingElement("g")) {
        const char* mode = g->Attribute("inkscape:groupmode");
        if (mode && std::string(mode) == "layer") svg.layers.push_back(g->Attribute("inkscape:label"));
        for (const tinyxml2::XMLElement* c = g->FirstChildElement("circle"); c; c = c->NextSiblingElement("circle"))
            svg.dots.emplace_back(c->DoubleAttribute("cx"), c->DoubleAttribute("cy"));
    }
    return svg;
}

// The PNG, its mask and the vector files of one view, the page the image's size in mm (1 mm a pixel).
// `min_dots`: enough that the figures mean something (a close-up's few enlarged dots ink as much as many).
void expect_vector_is_the_png(const std::string& name, std::vector<std::string> model_args, size_t min_dots = 1000) {
    for (const char* tool : {"rsvg-convert", "pdftoppm"})
        if (!have_tool(tool)) GTEST_SKIP() << tool << " is not installed (librsvg2-bin, poppler-utils)";
    const auto dir = test::temp_dir("cli-export-" + name);
    const std::string png = (dir / "frame.png").string(), mask = (dir / "mask.png").string();
    const std::string svg = (dir / "frame.svg").string(), pdf = (dir / "frame.pdf").string();
    std::vector<std::string> size = {"--width", std::to_string(kWidth), "--height", std::to_string(kHeight)};
    std::vector<std::string> page = {"--page", std::to_string(kWidth) + "x" + std::to_string(kHeight) + "mm",
                                     "--margin", "0", "--fit", "frame"};
    auto args = [&](std::vector<std::string> extra) {
        std::vector<std::string> all = {"render"};
        all.insert(all.end(), model_args.begin(), model_args.end());
        all.insert(all.end(), size.begin(), size.end());
        all.insert(all.end(), extra.begin(), extra.end());
        return all;
    };
    run_ok(args({"-o", png, "--mask", mask}));
    std::vector<std::string> svg_args = {"-o", svg}, pdf_args = {"-o", pdf};
    svg_args.insert(svg_args.end(), page.begin(), page.end());
    pdf_args.insert(pdf_args.end(), page.begin(), page.end());
    const std::string svg_said = run_ok(args(svg_args));
    run_ok(args(pdf_args));
    const std::string w = std::to_string(kWidth * kSuper), h = std::to_string(kHeight * kSuper);
    shell_ok("rsvg-convert -w " + w + " -h " + h + " -b white '" + svg + "' -o '" + (dir / "svg8.png").string() + "'");
    shell_ok("pdftoppm -png -singlefile -scale-to-x " + w + " -scale-to-y " + h + " '" + pdf + "' '" +
             (dir / "pdf8").string() + "'");

    const Image frame = read_png(png), coverage = read_png(mask);
    const double ink_png = mean_ink_inside(frame, coverage);
    const double ink_svg = mean_ink_inside(read_png((dir / "svg8.png").string()), coverage);
    const double ink_pdf = mean_ink_inside(read_png((dir / "pdf8.png").string()), coverage);
    std::printf("%s: mean ink inside the object: PNG %.4f, SVG %.4f (%.3f), PDF %.4f (%.3f)\n", name.c_str(), ink_png,
                ink_svg, ink_svg / ink_png, ink_pdf, ink_pdf / ink_png);
    EXPECT_GT(ink_png, 0.02);
    EXPECT_NEAR(ink_svg / ink_png, 1.0, 0.03);
    EXPECT_NEAR(ink_pdf / ink_png, 1.0, 0.03);

    const Svg doc = read_svg(svg);
    EXPECT_EQ(doc.width, std::to_string(kWidth) + "mm");
    EXPECT_EQ(doc.height, std::to_string(kHeight) + "mm");
    EXPECT_EQ(doc.view_box, "0 0 " + std::to_string(kWidth) + " " + std::to_string(kHeight));
    ASSERT_FALSE(doc.layers.empty());
    EXPECT_EQ(doc.layers[0].substr(0, 2), "1 ") << "an AxiDraw layer label starts with its number";
    ASSERT_GT(doc.dots.size(), min_dots);
    // The closing line names the page and what is on it.
    const std::string said = "wrote " + svg + " (" + std::to_string(kWidth) + "x" + std::to_string(kHeight) +
                             " mm page: " + std::to_string(doc.dots.size()) + " dots, ";
    EXPECT_NE(svg_said.find(said), std::string::npos) << svg_said;
    size_t on_ink = 0;
    for (const auto& [x, y] : doc.dots) on_ink += darkness(frame, int(x), int(y)) > 0.0;
    const double share = double(on_ink) / double(doc.dots.size());
    const double bytes = double(std::filesystem::file_size(svg)) / double(doc.dots.size());
    std::printf("%s: %zu dots, %.2f%% of their centres on inked pixels, %.1f bytes per dot\n", name.c_str(),
                doc.dots.size(), 100.0 * share, bytes);
    EXPECT_GE(share, 0.99);
    EXPECT_LE(bytes, 48.0);

    // The PDF's page: the requested size in points (1 mm = 72 / 25.4 pt).
    std::ifstream in(pdf, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    char box[96];
    std::snprintf(box, sizeof box, "/MediaBox [ 0 0 %g %g ]", kWidth * 72.0 / 25.4, kHeight * 72.0 / 25.4);
    const std::string contents = text.str();
    const size_t at = contents.find("/MediaBox");
    ASSERT_NE(at, std::string::npos);
    double pw = 0, ph = 0;
    ASSERT_EQ(std::sscanf(contents.c_str() + at, "/MediaBox [ 0 0 %lf %lf", &pw, &ph), 2) << contents.substr(at, 60);
    EXPECT_NEAR(pw, kWidth * 72.0 / 25.4, 0.01);
    EXPECT_NEAR(ph, kHeight * 72.0 / 25.4, 0.01);
}

TEST(CliExport, TheDefaultSceneAsSvgAndPdfIsItsPng) { expect_vector_is_the_png("default", {}); }

// Close up the candidates cannot carry the density, and the frame draws them as larger dots (stipple_scale):
// the vector files draw the same dots. Until 2026-12-05 they drew every dot at the point size, and at 0.3
// of the framing distance the SVG and the PDF read 0.68 and 0.69 of the PNG's ink (now 1.00 and 1.02).
TEST(CliExport, EnlargedDotsCloseUpAreEnlargedInTheSvgAndPdf) {
    expect_vector_is_the_png("close-up", {"--distance", "0.3"});
}

// The same on a steep surface: a floor of 40 x 40 cells seen from above at 80 degrees and close, its dots
// enlarged up to 6-px squares. Square dots were tested against the depth pass flat, at their centre's depth,
// and on the steep slope an enlarged one lost a row of its pixels behind its own surface: the SVG read 1.14
// times the PNG's ink (until 2026-12-05; now enlarged squares are pulled onto their surface as round dots are).
TEST(CliExport, EnlargedDotsOnASteepSurfaceAreWholeInThePng) {
    const auto dir = test::temp_dir("cli-export-steep");
    std::string obj;
    const int n = 40;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            obj += "v " + std::to_string(-10.0 + 20.0 * i / n) + " 0 " + std::to_string(-10.0 + 20.0 * j / n) + "\n";
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
            obj += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(b) + "\nf " + std::to_string(b) +
                   " " + std::to_string(c) + " " + std::to_string(d) + "\n";
        }
    const std::string model = test::write_file(dir / "floor.obj", obj);
    const std::string scene = test::write_file(
        dir / "steep.json", "{\"objects\": [{\"model\": \"" + model +
                                "\"}], \"camera\": {\"target\": [3, 0, -2], \"world_distance\": 1.2, \"yaw\": 30, \"pitch\": 80}}");
    expect_vector_is_the_png("steep-floor", {scene}, 200);  // 271 dots, most of them 6 px wide
}

TEST(CliExport, TheBunnyAsSvgAndPdfIsItsPng) {
    const std::string bunny = test::shared_model("stanford-bunny.obj");
    if (bunny.empty()) GTEST_SKIP() << "../shared/models/stanford-bunny.obj is absent";
    expect_vector_is_the_png("bunny", {bunny, "--yaw", "30", "--pitch", "10"});
}

// A small copy of the default scene's blob inside the big one: every stipple of it is hidden (§2.1's
// hidden-stipple removal), so it gets no dot, while the outer object gets thousands.
TEST(CliExport, AHiddenObjectContributesNoDot) {
    const auto dir = test::temp_dir("cli-export-hidden");
    const std::string blobby = test::source_path("assets/blobby.glb");
    std::ofstream(dir / "scene.json") << R"({"objects": [{"model": ")" << blobby << R"("},
        {"model": ")" << blobby << R"(", "transform": {"scale": 0.3}}]})";
    const std::string csv = (dir / "dots.csv").string();
    run_ok({"render", (dir / "scene.json").string(), "-o", csv, "--width", "400", "--height", "320"});
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "x_mm,y_mm,radius_mm,object,polygon");
    size_t outer = 0, inner = 0;
    while (std::getline(in, line)) {
        std::stringstream fields(line);
        std::string x, y, r, object;
        std::getline(fields, x, ','), std::getline(fields, y, ','), std::getline(fields, r, ','), std::getline(fields, object, ',');
        (object == "0" ? outer : inner) += 1;
    }
    std::printf("dots: %zu of the outer object, %zu of the hidden one\n", outer, inner);
    EXPECT_GT(outer, 1000u);
    EXPECT_EQ(inner, 0u);
}

// --stats with vector output prints two counts: the stipples the density drew and the plot's dots, those of
// them left visible by hidden-stipple removal; each says which it is (they differed without a word).
TEST(CliExport, StatsSayWhichCountIsWhich) {
    const auto dir = test::temp_dir("cli-export-stats");
    const std::string said = run_ok({"render", "-o", (dir / "x.svg").string(), "--width", "320", "--height", "256", "--stats"});
    const std::string drawn_label = "drawn stipples:     ", plot_label = "plot: ";
    const size_t drawn_at = said.find(drawn_label), plot_at = said.find(plot_label);
    ASSERT_NE(drawn_at, std::string::npos) << said;
    ASSERT_NE(plot_at, std::string::npos) << said;
    const long drawn = std::stol(said.substr(drawn_at + drawn_label.size()));
    const long dots = std::stol(said.substr(plot_at + plot_label.size()));
    std::printf("drawn %ld, plotted %ld\n", drawn, dots);
    EXPECT_NE(said.find("(by the density, before hidden-stipple removal; the plot's dots are those visible)"), std::string::npos) << said;
    EXPECT_GT(dots, 0.5 * double(drawn));
    EXPECT_LT(dots, drawn) << "the default scene hides some of the stipples the density draws";
    const std::string png = run_ok({"render", "-o", (dir / "x.png").string(), "--width", "320", "--height", "256", "--stats"});
    // A PNG's count says what it counts too (a tester read it as the dots seen), without a plot to point to.
    EXPECT_NE(png.find("(by the density, before hidden-stipple removal)\n"), std::string::npos) << png;
    EXPECT_EQ(png.find("the plot's dots"), std::string::npos) << "a PNG has no plot to tell apart";
}

// --show-travel (the README's plot-order picture): the SVG gains the pen's path with the pen up, one
// move to each dot, in a plain group after the layers; without it the file has none; PDF refuses it.
TEST(CliExport, ShowTravelAddsThePenUpMovesToTheSvg) {
    const auto dir = test::temp_dir("cli-export-travel");
    const std::string plain = (dir / "plain.svg").string(), travel = (dir / "travel.svg").string();
    const std::vector<std::string> view = {"render", "--width", "200", "--height", "160"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> all = view;
        all.insert(all.end(), extra.begin(), extra.end());
        return all;
    };
    run_ok(with({"-o", plain}));
    run_ok(with({"-o", travel, "--show-travel"}));
    auto text_of = [](const std::string& path) {
        std::ifstream in(path);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    const std::string a = text_of(plain), b = text_of(travel);
    EXPECT_EQ(a.find("pen-up-travel"), std::string::npos);
    const size_t group = b.find("id=\"pen-up-travel\"");
    ASSERT_NE(group, std::string::npos) << "no travel group";
    const Svg with_travel = read_svg(travel);
    ASSERT_FALSE(with_travel.layers.empty());
    EXPECT_EQ(with_travel.layers.back(), "% pen-up travel (not plotted)") << "a layer the AxiDraw software does not plot";
    const size_t moves = size_t(std::count(b.begin() + group, b.end(), 'M'));
    const size_t dots = read_svg(travel).dots.size();
    std::printf("%zu dots, %zu pen-up moves\n", dots, moves);
    EXPECT_GT(dots, 100u);
    EXPECT_EQ(moves, dots);  // the default scene has no lines: one move to each dot
    EXPECT_EQ(read_svg(plain).dots.size(), dots);  // the same drawing otherwise

    const test::CommandResult pdf = test::run_stipple(with({"-o", (dir / "x.pdf").string(), "--show-travel"}));
    EXPECT_NE(pdf.exit_code, 0);
    EXPECT_NE(pdf.err.find("--show-travel"), std::string::npos) << pdf.err;
    EXPECT_EQ(std::count(pdf.err.begin(), pdf.err.end(), '\n'), 1) << pdf.err;
}

// Tick dots (plotters) are drawn from the end nearer where the pen was: drawn all left to right, the pen crossed
// back over each tick, and --stats, measuring between the ticks' centres, said about half the pen-up travel the
// file made (the spot: 12,833 mm said, 24,791 in the file). Now the stats, the travel layer and the strokes are
// one path. And the same command writes the same file: the stipples came back from the GPU in any order, and the
// chance by which a dot under the pen's least mark is drawn followed that order (7,803 or 7,801 ticks).
TEST(CliExport, TicksAreDrawnFromTheirNearerEndTheSameEveryRun) {
    const auto dir = test::temp_dir("cli-export-ticks");
    const std::string a = (dir / "a.svg").string(), b = (dir / "b.svg").string();
    const std::vector<std::string> args = {"render", "--width", "320", "--height", "256", "--dot-style", "tick", "--pen-width",
                                           "0.3", "--show-travel", "--stats", "-o"};
    std::vector<std::string> first = args, second = args;
    first.push_back(a), second.push_back(b);
    const std::string said = run_ok(first);
    run_ok(second);
    auto text_of = [](const std::string& path) {
        std::ifstream in(path);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    const std::string svg = text_of(a);
    EXPECT_EQ(svg, text_of(b)) << "two runs of one command wrote different files";
    // The ticks, "Mx yhL" one a line, and the travel layer's moves, "Mx yLx y".
    struct Tick {
        double x0, x1, y;
    };
    std::vector<Tick> ticks;
    std::vector<std::array<double, 4>> moves;
    const size_t travel_at = svg.find("id=\"pen-up-travel\"");
    ASSERT_NE(travel_at, std::string::npos);
    std::istringstream lines(svg);
    size_t offset = 0;
    for (std::string line; std::getline(lines, line); offset += line.size() + 1) {
        const size_t m = line.rfind('M');
        if (m == std::string::npos) continue;
        double x = 0, y = 0, h = 0, x2 = 0, y2 = 0;
        if (offset < travel_at && std::sscanf(line.c_str() + m, "M%lf %lfh%lf", &x, &y, &h) == 3) ticks.push_back({x, x + h, y});
        if (offset > travel_at && std::sscanf(line.c_str() + m, "M%lf %lfL%lf %lf", &x, &y, &x2, &y2) == 4) moves.push_back({x, y, x2, y2});
    }
    ASSERT_GT(ticks.size(), 500u);
    ASSERT_EQ(moves.size(), ticks.size()) << "one pen-up move to each tick (the default scene has no lines)";
    double travel = 0.0;
    size_t reversed = 0, from_farther_end = 0, moves_elsewhere = 0;
    for (size_t k = 0; k < ticks.size(); ++k) {
        const auto& mv = moves[k];
        travel += std::hypot(mv[2] - mv[0], mv[3] - mv[1]);
        reversed += ticks[k].x1 < ticks[k].x0;
        // Each move ends where its tick starts, and starts where the last tick ended.
        moves_elsewhere += std::hypot(mv[2] - ticks[k].x0, mv[3] - ticks[k].y) > 0.015;
        if (k == 0) continue;
        moves_elsewhere += std::hypot(mv[0] - ticks[k - 1].x1, mv[1] - ticks[k - 1].y) > 0.015;
        const double from_start = std::hypot(ticks[k].x0 - ticks[k - 1].x1, ticks[k].y - ticks[k - 1].y);
        const double from_end = std::hypot(ticks[k].x1 - ticks[k - 1].x1, ticks[k].y - ticks[k - 1].y);
        from_farther_end += from_start > from_end + 0.015;
    }
    const size_t at = said.find("pen up ");
    ASSERT_NE(at, std::string::npos) << said;
    const double stated = std::stod(said.substr(at + 7));
    std::printf("%zu ticks, %zu drawn right to left, %zu from their farther end; pen up %.1f mm in the file, %.1f said\n",
                ticks.size(), reversed, from_farther_end, travel, stated);
    EXPECT_GT(reversed, ticks.size() / 5);
    EXPECT_EQ(from_farther_end, 0u);
    EXPECT_EQ(moves_elsewhere, 0u);
    EXPECT_NEAR(travel, stated, 0.002 * stated + 0.5);
}

// By default the drawing fills the page: the default scene's dots reach the margins on a page turned as the
// drawing is, where the whole frame (--fit frame) leaves paper around them; a frame sequence lines its
// pages up unless told; --fit is for vector output.
TEST(CliExport, TheDrawingFillsThePageUnlessTheFrameIsAsked) {
    const auto dir = test::temp_dir("cli-export-fit");
    const std::vector<std::string> view = {"render", "--width", "320", "--height", "256"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> all = view;
        all.insert(all.end(), extra.begin(), extra.end());
        return all;
    };
    // The dots' extent over the page's room inside its 10-mm margins, in the direction that fills most.
    auto filled = [](const Svg& doc) {
        double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
        for (const auto& [x, y] : doc.dots) {
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
        const double w = std::stod(doc.width), h = std::stod(doc.height);
        return std::max((x1 - x0) / (w - 20.0), (y1 - y0) / (h - 20.0));
    };
    const std::string fitted = (dir / "fitted.svg").string(), framed = (dir / "framed.svg").string();
    const std::string said = run_ok(with({"-o", fitted}));
    run_ok(with({"-o", framed, "--fit", "frame"}));
    const Svg drawing = read_svg(fitted), frame = read_svg(framed);
    ASSERT_GT(drawing.dots.size(), 500u);
    EXPECT_EQ(drawing.dots.size(), frame.dots.size());
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const auto& [x, y] : drawing.dots) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    const bool wide = x1 - x0 > y1 - y0;
    EXPECT_EQ(drawing.width, wide ? "297mm" : "210mm") << "A4 turned as the drawing is";
    EXPECT_EQ(frame.width, "297mm") << "A 320 x 256 frame is landscape";
    std::printf("the dots span %.3f of the page's room fitted, %.3f with the frame\n", filled(drawing), filled(frame));
    EXPECT_GT(filled(drawing), 0.97);
    EXPECT_LT(filled(frame), 0.9 * filled(drawing));
    EXPECT_NE(said.find("the drawing fitted to it"), std::string::npos) << said;

    const std::string sequence = run_ok(with({"-o", (dir / "f%d.svg").string(), "--frames", "2", "--orbit", "10"}));
    EXPECT_NE(sequence.find("the frame's view at 320x256"), std::string::npos) << sequence;
    EXPECT_EQ(read_svg((dir / "f0.svg").string()).view_box, frame.view_box);

    const test::CommandResult png = test::run_stipple(with({"-o", (dir / "x.png").string(), "--fit", "frame"}));
    EXPECT_NE(png.exit_code, 0);
    EXPECT_NE(png.err.find("--fit is for vector output"), std::string::npos) << png.err;
    const test::CommandResult bad = test::run_stipple(with({"-o", (dir / "y.svg").string(), "--fit", "page"}));
    EXPECT_NE(bad.exit_code, 0);
    EXPECT_NE(bad.err.find("--fit 'page': expected drawing or frame"), std::string::npos) << bad.err;
}

// A page with nothing on it is written, and said: the object is out of view, or too far or too light.
TEST(CliExport, ABlankPageIsSaid) {
    const auto dir = test::temp_dir("cli-export-blank");
    const std::string out = (dir / "blank.svg").string();
    const test::CommandResult r = test::run_stipple({"render", "--width", "200", "--height", "160", "--distance", "1000", "-o", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("stipple: warning: " + out + ": nothing is drawn (no dot, no line)"), std::string::npos) << r.err;
    EXPECT_TRUE(read_svg(out).dots.empty());
    const test::CommandResult drawn = test::run_stipple({"render", "--width", "200", "--height", "160", "-o", out});
    EXPECT_EQ(drawn.err.find("nothing is drawn"), std::string::npos) << drawn.err;
    // A PNG of bare paper is said the same way (it was written without a word).
    const std::string png = (dir / "blank.png").string();
    const test::CommandResult bare = test::run_stipple({"render", "--width", "200", "--height", "160", "--distance", "1000", "-o", png});
    ASSERT_EQ(bare.exit_code, 0) << bare.err;
    EXPECT_NE(bare.err.find("stipple: warning: " + png + ": nothing is drawn (no dot, no line)"), std::string::npos) << bare.err;
    const test::CommandResult inked = test::run_stipple({"render", "--width", "200", "--height", "160", "-o", png});
    EXPECT_EQ(inked.err.find("nothing is drawn"), std::string::npos) << inked.err;
    // A frame that one line inks all over is drawn (2 x 2 pixels of outline were said blank); a frame that faces
    // which only hide cover in paper is blank (seen from inside a box open on one side, under contours, whose
    // open side makes the faces facing away hide: said drawn, since the surface covered every pixel).
    const test::CommandResult tiny =
        test::run_stipple({"render", "--width", "2", "--height", "2", "--silhouette-lines", "--silhouette-width", "8", "-o", png});
    ASSERT_EQ(tiny.exit_code, 0) << tiny.err;
    EXPECT_EQ(tiny.err.find("nothing is drawn"), std::string::npos) << tiny.err;
    const std::string box = (dir / "open_box.obj").string();
    {
        std::ofstream obj(box);
        obj << "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
               "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\n";  // no +x face
    }
    const test::CommandResult inside = test::run_stipple(
        {"render", box, "--distance", "0.05", "--contours", "--width", "64", "--height", "64", "-o", png, "--stats"});
    ASSERT_EQ(inside.exit_code, 0) << inside.err;
    EXPECT_NE(inside.out.find("covered pixels:     4096"), std::string::npos) << inside.out;
    EXPECT_NE(inside.err.find("stipple: warning: " + png + ": nothing is drawn (no dot, no line)"), std::string::npos) << inside.err;
}

// SOURCE_DATE_EPOCH dates a PDF so that the same command writes the same bytes; a value that is not a whole
// number of seconds is said in one warning (it was ignored without a word, the PDF dated now) and the PDF written.
TEST(CliExport, AMalformedSourceDateIsSaid) {
    const auto dir = test::temp_dir("cli-export-source-date");
    const std::string out = (dir / "dated.pdf").string();
    for (const char* value : {"abc", "-5", "1e9", "99999999999999999999"}) {
        test::ScopedEnv date("SOURCE_DATE_EPOCH", value);
        const test::CommandResult r = test::run_stipple({"render", "--width", "160", "--height", "128", "-o", out});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.err.find(std::string("stipple: warning: SOURCE_DATE_EPOCH=") + value + " is not a whole number of seconds"),
                  std::string::npos) << r.err;
        EXPECT_TRUE(std::filesystem::exists(out));
    }
    test::ScopedEnv date("SOURCE_DATE_EPOCH", "1764900000");
    const test::CommandResult r = test::run_stipple({"render", "--width", "160", "--height", "128", "-o", out});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("SOURCE_DATE_EPOCH"), std::string::npos) << r.err;
}

// What each format can hold: a PDF page of at most 5080 mm a side (ISO 32000; readers refuse larger
// ones), refused before anything is drawn, where an SVG takes any page; a CSV, the dots alone, which
// the command's last line says where lines were drawn.
TEST(CliExport, EachFormatSaysWhatItCannotHold) {
    const auto dir = test::temp_dir("cli-export-formats");
    const std::vector<std::string> view = {"render", "--width", "200", "--height", "160", "--page", "6000x4000mm"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> all = view;
        all.insert(all.end(), extra.begin(), extra.end());
        return all;
    };
    const std::string pdf_path = (dir / "big.pdf").string();
    const test::CommandResult pdf = test::run_stipple(with({"-o", pdf_path}));
    EXPECT_NE(pdf.exit_code, 0);
    EXPECT_NE(pdf.err.find(pdf_path + ": a PDF page is at most 5080 mm (200 in) a side, and this page is 6000 x 4000 mm"),
              std::string::npos) << pdf.err;
    EXPECT_EQ(std::count(pdf.err.begin(), pdf.err.end(), '\n'), 1) << pdf.err;
    EXPECT_FALSE(std::filesystem::exists(pdf_path));
    run_ok(with({"-o", (dir / "big.svg").string()}));
    // A page of fractions of a millimetre is named as given (it said 101x151 for 100.9x150.7).
    const test::CommandResult odd = test::run_stipple(
        {"render", "--width", "200", "--height", "160", "--page", "100.9x150.7mm", "-o", (dir / "odd.svg").string()});
    ASSERT_EQ(odd.exit_code, 0) << odd.err;
    EXPECT_NE(odd.out.find("(100.9x150.7 mm page: "), std::string::npos) << odd.out;

    const test::CommandResult csv =
        test::run_stipple({"render", "--width", "200", "--height", "160", "--contours", "-o", (dir / "dots.csv").string()});
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    EXPECT_NE(csv.out.find("polylines are not written to CSV"), std::string::npos) << csv.out;
}

}  // namespace
}  // namespace stipple
