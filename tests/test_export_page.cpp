// Page names, orientation, margins and fitting the image onto the page.
#include <gtest/gtest.h>

#include "export/page.hpp"
#include "support/export_helpers.hpp"

namespace {

using namespace stipple::plot;

TEST(ExportPage, NamedSizesArePortraitUnlessTold) {
    EXPECT_DOUBLE_EQ(parse_page("A4").width_mm, 210.0);
    EXPECT_DOUBLE_EQ(parse_page("a4").height_mm, 297.0);
    EXPECT_DOUBLE_EQ(parse_page("A3").width_mm, 297.0);
    EXPECT_DOUBLE_EQ(parse_page("A3").height_mm, 420.0);
    EXPECT_DOUBLE_EQ(parse_page("A5").width_mm, 148.0);
    EXPECT_DOUBLE_EQ(parse_page("letter").width_mm, 215.9);
    EXPECT_DOUBLE_EQ(parse_page("Legal").height_mm, 355.6);
    const PageSize landscape = parse_page("A4-landscape");
    EXPECT_DOUBLE_EQ(landscape.width_mm, 297.0);
    EXPECT_DOUBLE_EQ(landscape.height_mm, 210.0);
    EXPECT_DOUBLE_EQ(parse_page("A4-portrait").width_mm, 210.0);
}

TEST(ExportPage, CustomSizesKeepTheirShapeUnlessAnOrientationIsNamed) {
    const PageSize wide = parse_page("300x200mm");
    EXPECT_DOUBLE_EQ(wide.width_mm, 300.0);
    EXPECT_DOUBLE_EQ(wide.height_mm, 200.0);
    const PageSize turned = parse_page("300x200mm-portrait");
    EXPECT_DOUBLE_EQ(turned.width_mm, 200.0);
    EXPECT_DOUBLE_EQ(turned.height_mm, 300.0);
    EXPECT_DOUBLE_EQ(parse_page("152.4x101.6MM").width_mm, 152.4);
}

TEST(ExportPage, BadNamesAreOneLineErrors) {
    stipple::test::expect_plot_error([] { parse_page("210 x 297 mm"); }, "no spaces");
    for (const char* bad : {"A9", "", "x200mm", "300xmm", "0x200mm", "-3x200mm", "300x200", "300x200cm", "300x200mm-sideways", "1e9x10mm", "nanx10mm"})
        stipple::test::expect_plot_error([&] { parse_page(bad); }, "--page");
    // Beyond a double's range: said too large or too small, not "not a positive number".
    stipple::test::expect_plot_error([] { parse_page("1e400x100mm"); }, "larger than 10 m");
    stipple::test::expect_plot_error([] { parse_page("100x1e-400mm"); }, "smaller than 10 mm");
    stipple::test::expect_plot_error([] { parse_page("nanx100mm"); }, "positive numbers");
}

TEST(ExportPage, FitsUniformlyAndCentred) {
    // A 1280x1024 image on A4 portrait with 10 mm margins: the width limits (190 mm).
    const PageLayout layout = fit_to_page(parse_page("A4"), 10.0, 1280.0, 1024.0);
    EXPECT_NEAR(layout.mm_per_px, 190.0 / 1280.0, 1e-12);
    const glm::dvec2 top_left = layout.to_mm({0.0, 0.0}), bottom_right = layout.to_mm({1280.0, 1024.0});
    EXPECT_NEAR(top_left.x, 10.0, 1e-9);
    EXPECT_NEAR(bottom_right.x, 200.0, 1e-9);
    EXPECT_NEAR(top_left.y + bottom_right.y, 297.0, 1e-9);  // centred vertically
    EXPECT_NEAR(bottom_right.y - top_left.y, 1024.0 * 190.0 / 1280.0, 1e-9);

    // A tall image on landscape A4: the height limits, centred horizontally.
    const PageLayout tall = fit_to_page(parse_page("A4-landscape"), 5.0, 100.0, 400.0);
    EXPECT_NEAR(tall.mm_per_px, 200.0 / 400.0, 1e-12);
    EXPECT_NEAR(tall.to_mm({0.0, 0.0}).x + tall.to_mm({100.0, 0.0}).x, 297.0, 1e-9);
    EXPECT_NEAR(tall.to_mm({0.0, 0.0}).y, 5.0, 1e-9);
}

// A bare named size takes the drawing's orientation (a landscape frame on portrait A4 used a third of the
// paper); one whose orientation is named, and WxHmm, keep theirs.
TEST(ExportPage, ABareNamedSizeIsTurnedAsTheDrawingIs) {
    const PageSize wide = oriented_for(parse_page("A4"), 1280.0, 1024.0);
    EXPECT_DOUBLE_EQ(wide.width_mm, 297.0);
    EXPECT_DOUBLE_EQ(wide.height_mm, 210.0);
    const PageSize tall = oriented_for(parse_page("letter"), 300.0, 1024.0);
    EXPECT_DOUBLE_EQ(tall.width_mm, 215.9);
    EXPECT_DOUBLE_EQ(tall.height_mm, 279.4);
    EXPECT_DOUBLE_EQ(oriented_for(parse_page("A3-portrait"), 1280.0, 1024.0).width_mm, 297.0) << "named: kept";
    EXPECT_DOUBLE_EQ(oriented_for(parse_page("A3-landscape"), 100.0, 1024.0).width_mm, 420.0) << "named: kept";
    EXPECT_DOUBLE_EQ(oriented_for(parse_page("200x300mm"), 1280.0, 1024.0).width_mm, 200.0) << "as written: kept";
    EXPECT_DOUBLE_EQ(oriented_for(parse_page("A5"), 500.0, 500.0).width_mm, 148.0) << "square: portrait";
}

// Any area of the image may be fitted: its centre lands on the page's centre.
TEST(ExportPage, AnAreaOfTheImageIsFittedAndCentred) {
    const PageLayout layout = fit_to_page(parse_page("A4-landscape"), 10.0, glm::dvec2(300.0, 200.0), glm::dvec2(500.0, 300.0));
    EXPECT_NEAR(layout.mm_per_px, 277.0 / 200.0, 1e-12);  // 2:1 on 277 x 190 mm: the width limits
    EXPECT_NEAR(layout.to_mm({300.0, 0.0}).x, 10.0, 1e-9);
    EXPECT_NEAR(layout.to_mm({500.0, 0.0}).x, 287.0, 1e-9);
    EXPECT_NEAR(layout.to_mm({0.0, 250.0}).y, 105.0, 1e-9);
}

TEST(ExportPage, BadMarginsAndEmptyImagesAreErrors) {
    stipple::test::expect_plot_error([] { fit_to_page(parse_page("A4"), -1.0, 100.0, 100.0); }, "--margin -1");
    stipple::test::expect_plot_error([] { fit_to_page(parse_page("A5"), 74.0, 100.0, 100.0); }, "leaves no room");
    stipple::test::expect_plot_error([] { fit_to_page(parse_page("A4"), 10.0, 0.0, 100.0); }, "no size");
}

}  // namespace
