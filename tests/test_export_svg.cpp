// The SVG: a millimetre page, one Inkscape layer per object and kind with the styles on the
// layer, the dots and strokes of the plan in order, at most 48 bytes a dot; and, rasterised by
// rsvg-convert, ink exactly where the dots are.
#include <gtest/gtest.h>

#include <tinyxml2.h>

#include <cmath>
#include <cstring>
#include <cctype>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>

#include "core/utf8.hpp"
#include "export/blue_noise.hpp"
#include "export/plot_plan.hpp"
#include "export/svg_writer.hpp"
#include "export/text_format.hpp"
#include "io/png_io.hpp"
#include "support/export_helpers.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace {

using namespace stipple::plot;
using stipple::test::grid_drawing;

// Two objects: "bunny" with a grid of dots and a square outline, "horse & co" with dots only.
Drawing two_objects() {
    Drawing d = grid_drawing(10, 10);
    d.objects[0].name = "bunny";
    d.objects.push_back({"horse & co", 1.0f});
    for (int i = 0; i < 25; ++i) d.dots.push_back({glm::vec2(300.0f + 8.0f * (i % 5), 230.0f + 8.0f * (i / 5)), 1.0f, 1.0f, 1, 7});
    return d;
}

std::vector<const tinyxml2::XMLElement*> layers_of(const tinyxml2::XMLElement* svg) {
    std::vector<const tinyxml2::XMLElement*> layers;
    for (const tinyxml2::XMLElement* g = svg->FirstChildElement("g"); g; g = g->NextSiblingElement("g"))
        if (g->Attribute("inkscape:groupmode", "layer")) layers.push_back(g);
    return layers;
}

size_t count_children(const tinyxml2::XMLElement* parent, const char* name) {
    size_t n = 0;
    for (const tinyxml2::XMLElement* e = parent->FirstChildElement(name); e; e = e->NextSiblingElement(name)) ++n;
    return n;
}

// About `count` dots spread evenly over a 1280 x 1024 frame, of radius `radius` px and intensities from
// `least` to 1.
Drawing spread_dots(size_t count, float radius, float least) {
    Drawing drawing;
    drawing.width_px = 1280;
    drawing.height_px = 1024;
    drawing.objects.push_back({"bunny", 1.0f});
    for (const glm::dvec2& p : poisson_disc_points(1280.0, 1024.0, poisson_disc_spacing(1280.0, 1024.0, count), 8))
        drawing.dots.push_back({glm::vec2(p), radius, least + (1.0f - least) * float(std::fmod(p.x * 7.31, 1.0)), 0, 0});
    return drawing;
}

TEST(ExportSvg, PageLayersAndCounts) {
    ExportOptions options;
    options.page = parse_page("A4-landscape");
    options.margin_mm = 15.0;
    const PlotPlan plan = make_plot_plan(two_objects(), options);
    const std::string text = svg_document(plan);

    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(text.c_str(), text.size()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
    const tinyxml2::XMLElement* svg = doc.RootElement();
    ASSERT_STREQ(svg->Name(), "svg");
    EXPECT_STREQ(svg->Attribute("width"), "297mm");
    EXPECT_STREQ(svg->Attribute("height"), "210mm");
    EXPECT_STREQ(svg->Attribute("viewBox"), "0 0 297 210");
    EXPECT_STREQ(svg->Attribute("xmlns:inkscape"), "http://www.inkscape.org/namespaces/inkscape");

    const auto layers = layers_of(svg);
    ASSERT_EQ(layers.size(), 3u);
    EXPECT_STREQ(layers[0]->Attribute("inkscape:label"), "1 bunny stipples");
    EXPECT_STREQ(layers[1]->Attribute("inkscape:label"), "2 bunny lines");
    EXPECT_STREQ(layers[2]->Attribute("inkscape:label"), "4 horse & co stipples");
    // Styles on the layer, none on the dots.
    EXPECT_STREQ(layers[0]->Attribute("fill"), "#000000");
    EXPECT_STREQ(layers[1]->Attribute("fill"), "none");
    // No pen width given: the lines keep the frame's width (2 px) on the page's scale.
    EXPECT_NEAR(layers[1]->DoubleAttribute("stroke-width"), 2.0 * plan.layout.mm_per_px, 0.001);
    EXPECT_EQ(count_children(layers[0], "circle"), 100u);
    EXPECT_EQ(count_children(layers[2], "circle"), 25u);
    for (const tinyxml2::XMLElement* c = layers[0]->FirstChildElement("circle"); c; c = c->NextSiblingElement("circle")) {
        EXPECT_EQ(c->Attribute("fill"), nullptr);
        EXPECT_EQ(c->Attribute("style"), nullptr);
        // Inside the margins: the image is fitted within them.
        EXPECT_GE(c->DoubleAttribute("cx"), 15.0);
        EXPECT_LE(c->DoubleAttribute("cx"), 297.0 - 15.0);
        EXPECT_GE(c->DoubleAttribute("cy"), 15.0);
        EXPECT_LE(c->DoubleAttribute("cy"), 210.0 - 15.0);
        EXPECT_NEAR(c->DoubleAttribute("r"), 1.5 * plan.layout.mm_per_px, 0.001);
    }
    // The square outline: one closed path, its four corners.
    ASSERT_EQ(count_children(layers[1], "path"), 1u);
    const std::string d = layers[1]->FirstChildElement("path")->Attribute("d");
    EXPECT_EQ(d.back(), 'Z');
    std::string numbers = d;
    for (char& c : numbers) c = std::isalpha(static_cast<unsigned char>(c)) ? ' ' : c;
    std::istringstream in(numbers);
    std::vector<double> coords;
    for (double v; in >> v;) coords.push_back(v);
    ASSERT_EQ(coords.size(), 8u);  // 4 points
    const glm::dvec2 corner = plan.layout.to_mm({250.0, 100.0});
    bool has_corner = false;
    for (size_t i = 0; i < 8; i += 2) has_corner |= std::abs(coords[i] - corner.x) < 0.006 && std::abs(coords[i + 1] - corner.y) < 0.006;
    EXPECT_TRUE(has_corner);
}

// An object with an ink of its own draws its layers in it (a pen of that colour on a plotter), the others
// in the drawing's.
TEST(ExportSvg, EachObjectsLayersTakeItsInk) {
    Drawing drawing = two_objects();
    drawing.ink = glm::vec3(0.0f, 0.0f, 1.0f);
    drawing.objects[0].ink = glm::vec3(1.0f, 0.0f, 0.0f);
    const std::string text = svg_document(make_plot_plan(drawing, ExportOptions{}));
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(text.c_str(), text.size()), tinyxml2::XML_SUCCESS) << doc.ErrorStr();
    const auto layers = layers_of(doc.RootElement());
    ASSERT_EQ(layers.size(), 3u);
    EXPECT_STREQ(layers[0]->Attribute("fill"), "#ff0000");    // 1 bunny stipples
    EXPECT_STREQ(layers[1]->Attribute("stroke"), "#ff0000");  // 2 bunny lines
    EXPECT_STREQ(layers[2]->Attribute("fill"), "#0000ff");    // 4 horse & co stipples: the drawing's ink
}

TEST(ExportSvg, DotStylesForPlotters) {
    Drawing drawing = grid_drawing(4, 3);
    ExportOptions options;
    options.dot_style = DotStyle::Tick;
    options.pen_width_mm = 0.5;
    std::string text = svg_document(make_plot_plan(drawing, options));
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(text.c_str(), text.size()), tinyxml2::XML_SUCCESS);
    auto layers = layers_of(doc.RootElement());
    ASSERT_EQ(layers.size(), 2u);
    EXPECT_STREQ(layers[0]->Attribute("stroke-linecap"), "round");
    EXPECT_STREQ(layers[0]->Attribute("stroke-width"), "0.5");
    EXPECT_STREQ(layers[1]->Attribute("stroke-width"), "0.5");  // the pen draws the lines too
    EXPECT_EQ(count_children(layers[0], "circle"), 0u);
    const std::string ticks = layers[0]->FirstChildElement("path")->Attribute("d");
    EXPECT_EQ(std::count(ticks.begin(), ticks.end(), 'M'), 12);
    EXPECT_EQ(std::count(ticks.begin(), ticks.end(), 'h'), 12);

    options.dot_style = DotStyle::Circle;
    text = svg_document(make_plot_plan(drawing, options));
    ASSERT_EQ(doc.Parse(text.c_str(), text.size()), tinyxml2::XML_SUCCESS);
    layers = layers_of(doc.RootElement());
    EXPECT_STREQ(layers[0]->Attribute("fill"), "none");
    EXPECT_EQ(count_children(layers[0], "circle"), 12u);
}

// A pen finer than the 0.001 mm that coordinates are written to keeps its width: 0.0004 mm was written
// stroke-width="0", and every circle vanished.
TEST(ExportSvg, AThinPenKeepsItsWidth) {
    Drawing drawing = grid_drawing(4, 3);
    ExportOptions options;
    options.dot_style = DotStyle::Circle;
    for (const auto& [pen, written] : {std::pair<double, const char*>{0.0004, "0.0004"}, {0.0456, "0.0456"},
                                       {1.234e-5, "1.23e-05"}, {0.3, "0.3"}}) {
        options.pen_width_mm = pen;
        const std::string text = svg_document(make_plot_plan(drawing, options));
        tinyxml2::XMLDocument doc;
        ASSERT_EQ(doc.Parse(text.c_str(), text.size()), tinyxml2::XML_SUCCESS);
        const auto layers = layers_of(doc.RootElement());
        ASSERT_EQ(layers.size(), 2u);
        EXPECT_STREQ(layers[0]->Attribute("stroke-width"), written) << pen;  // the circles
        EXPECT_STREQ(layers[1]->Attribute("stroke-width"), written) << pen;  // the lines
        EXPECT_DOUBLE_EQ(layers[0]->DoubleAttribute("stroke-width"), std::stod(written));
    }
}

// On a page of a few millimetres a pixel is a hundredth of one: coordinates and radii are written finer, so
// that the dots keep their places and their ink (to 0.01 and 0.001 mm, a 12.5 mm page wrote every radius as
// one of 8 values and lost 7% of the ink; on a 10 mm page with 4.99 mm margins, every dot at one of 9 places).
TEST(ExportSvg, ATinyPageKeepsTheDotsPlacesAndInk) {
    const Drawing drawing = spread_dots(3000, 0.85f, 0.2f);
    for (const char* page : {"12.5x10mm", "A4"}) {
        ExportOptions options;
        options.page = parse_page(page);
        options.margin_mm = 0.0;
        const PlotPlan plan = make_plot_plan(drawing, options);
        const std::string text = svg_document(plan);
        tinyxml2::XMLDocument doc;
        ASSERT_EQ(doc.Parse(text.c_str(), text.size()), tinyxml2::XML_SUCCESS);
        double written_area = 0.0, planned_area = 0.0, worst_place = 0.0;
        std::set<std::pair<double, double>> places;
        std::vector<const PlotDot*> dots;
        for (const PlotLayer& layer : plan.layers)
            for (const PlotDot& dot : layer.dots) dots.push_back(&dot);
        size_t i = 0;
        for (const tinyxml2::XMLElement* layer : layers_of(doc.RootElement()))
            for (const tinyxml2::XMLElement* c = layer->FirstChildElement("circle"); c; c = c->NextSiblingElement("circle"), ++i) {
                ASSERT_LT(i, dots.size());
                const double r = c->DoubleAttribute("r");
                written_area += r * r;
                planned_area += dots[i]->radius_mm * dots[i]->radius_mm;
                worst_place = std::max(worst_place, glm::length(glm::dvec2(c->DoubleAttribute("cx"), c->DoubleAttribute("cy")) - dots[i]->mm));
                places.insert({c->DoubleAttribute("cx"), c->DoubleAttribute("cy")});
            }
        ASSERT_EQ(i, dots.size());
        std::printf("%s page: %zu dots at %zu places, worst place off by %.2f px, ink written / planned %.4f\n", page, dots.size(),
                    places.size(), worst_place / plan.layout.mm_per_px, written_area / planned_area);
        EXPECT_EQ(places.size(), dots.size()) << page;
        EXPECT_LT(worst_place, 0.06 * plan.layout.mm_per_px) << page;  // to a tenth of a pixel or finer
        EXPECT_NEAR(written_area / planned_area, 1.0, 0.01) << page;
    }
}

TEST(ExportSvg, AtMost48BytesPerDot) {
    const Drawing drawing = spread_dots(20000, 0.9f, 0.3f);
    ExportOptions options;
    options.page = parse_page("A3");
    const std::string text = svg_document(make_plot_plan(drawing, options));
    const double per_dot = double(text.size()) / double(drawing.dots.size());
    EXPECT_LE(per_dot, 48.0);
    RecordProperty("bytes_per_dot", std::to_string(per_dot));
}

TEST(ExportSvg, RasterisedInkIsWhereTheDotsAre) {
    if (!stipple::test::have_tool("rsvg-convert")) GTEST_SKIP() << "rsvg-convert (librsvg2-bin) not installed";
    Drawing drawing = grid_drawing(10, 10);
    for (Dot& dot : drawing.dots) dot.radius_px = 4.0f;
    drawing.segments.clear();
    ExportOptions options;
    options.page = parse_page("400x300mm");
    options.margin_mm = 0.0;  // 1 mm per pixel
    options.fit = Fit::Frame;
    options.fill_paper = true;
    const PlotPlan plan = make_plot_plan(drawing, options);
    const auto dir = stipple::test::temp_dir("export_svg_raster");
    write_svg(plan, (dir / "dots.svg").string());
    ASSERT_EQ(stipple::test::run_shell("rsvg-convert --width 400 --height 300 -o " + stipple::test::quoted(dir / "dots.png") + " " +
                                       stipple::test::quoted(dir / "dots.svg")),
              0);
    const stipple::Image image = stipple::read_png((dir / "dots.png").string());
    ASSERT_EQ(image.width, 400);
    for (const Dot& dot : drawing.dots) {
        EXPECT_LT(stipple::luminance(image, int(dot.px.x), int(dot.px.y)), 60) << dot.px.x << "," << dot.px.y;
        EXPECT_GT(stipple::luminance(image, int(dot.px.x) + 10, int(dot.px.y) + 10), 200);  // between dots: paper
    }
}

// An SVG is XML in UTF-8: a layer named after a file whose name is not UTF-8 (Latin-1 "caf\xe9") gets the
// replacement character, where the raw byte made a file no XML parser reads.
TEST(ExportSvg, TextThatIsNotUtf8IsMadeValid) {
    EXPECT_EQ(xml_escape("caf\xe9 <1>"), "caf\xef\xbf\xbd &lt;1&gt;");
    EXPECT_EQ(xml_escape("caf\xc3\xa9"), "caf\xc3\xa9");
    EXPECT_EQ(xml_escape("\xed\xa0\x80"), "\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd") << "a surrogate is not UTF-8";
    EXPECT_EQ(xml_escape("\xf0\x9f\x98\x80!"), "\xf0\x9f\x98\x80!") << "four bytes, one code point";
    EXPECT_EQ(xml_escape("\xc0\xaf"), "\xef\xbf\xbd\xef\xbf\xbd") << "an overlong form is not UTF-8";
    EXPECT_TRUE(stipple::is_valid_utf8(xml_escape("\xff\xfe\xe2\x82")));
}

TEST(ExportSvg, UnwritablePathIsOneLineError) {
    const PlotPlan plan = make_plot_plan(grid_drawing(2, 2), {});
    // Under a file, where no folder can be made (a missing folder is made: root could make /nonexistent-dir).
    const auto dir = stipple::test::temp_dir("export_svg_unwritable");
    const std::string file = (dir / "file").string();
    std::ofstream(file) << "a file";
    stipple::test::expect_plot_error([&] { write_svg(plan, file + "/x.svg"); }, file + "/x.svg: cannot write");
}

// A write that fails part way (a full disk; here the file-size limit) leaves the file that was there, and no
// part of the new one: it had left a truncated SVG in place of the good one.
TEST(ExportSvg, AFailedWriteLeavesTheFileThatWasThere) {
    stipple::test::expect_failed_write_keeps_the_file(
        "export_svg_failed_write", "x.svg", make_plot_plan(grid_drawing(2, 2), {}), make_plot_plan(grid_drawing(100, 100), {}),
        [](const std::string& path, const PlotPlan& plan) { write_svg(plan, path); }, "cannot write: File too large");
}

}  // namespace
