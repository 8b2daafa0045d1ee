// Print-resolution images (issue 15): `stipple render -o poster.png --page A3 --dpi 600` draws the page
// in tiles, each stipple a disc of the screen's share of ink, so that the print is the screen image
// enlarged. Downsampled to the screen image's size, its mean ink inside the object is the screen's;
// tiles join without seams (a tiled page is the page drawn in one piece).
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "io/png_io.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

void run_ok(const std::vector<std::string>& args) {
    const test::CommandResult r = test::run_stipple(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
}

double darkness(const Image& image, size_t x, size_t y) {
    const uint8_t* p = &image.pixels[(y * size_t(image.width) + x) * size_t(image.channels)];
    if (image.channels < 3) return 1.0 - p[0] / 255.0;  // grey (the coverage mask), maybe with alpha
    return 1.0 - (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255.0;
}

// Mean ink over the screen mask's covered pixels: of the screen image itself, and of the print's
// drawing (the page less its margin) box-filtered onto the screen's pixels.
struct InkPair {
    double screen = 0.0, print = 0.0;
};
// The screen image's place on the page: `dw` x `dh` pixels from (x0, y0).
InkPair ink_inside(const Image& screen, const Image& mask, const Image& page, int x0, int y0, int dw, int dh) {
    std::vector<double> sum(size_t(screen.width) * screen.height, 0.0);
    std::vector<uint32_t> count(sum.size(), 0);
    for (int y = 0; y < dh; ++y) {
        const size_t sy = size_t(y) * size_t(screen.height) / size_t(dh);
        for (int x = 0; x < dw; ++x) {
            const size_t sx = size_t(x) * size_t(screen.width) / size_t(dw);
            sum[sy * screen.width + sx] += darkness(page, size_t(x + x0), size_t(y + y0));
            ++count[sy * screen.width + sx];
        }
    }
    InkPair ink;
    size_t covered = 0;
    for (int y = 0; y < screen.height; ++y)
        for (int x = 0; x < screen.width; ++x) {
            if (darkness(mask, size_t(x), size_t(y)) > 0.5) continue;  // white where a surface covers
            const size_t i = size_t(y) * screen.width + x;
            ink.screen += darkness(screen, size_t(x), size_t(y));
            ink.print += sum[i] / double(std::max(1u, count[i]));
            ++covered;
        }
    ink.screen /= double(covered);
    ink.print /= double(covered);
    return ink;
}
InkPair ink_inside(const Image& screen, const Image& mask, const Image& page, int margin_px) {
    return ink_inside(screen, mask, page, margin_px, margin_px, page.width - 2 * margin_px, page.height - 2 * margin_px);
}

// A3 at 600 dpi with 10 mm margins: a 6543 x 9449 drawing, beyond the 4096-pixel tiles, so tiled.
// The screen image has the drawing's aspect (277:400) at 800 pixels high, the height --height gives
// the print's stipples.
TEST(CliPrint, A3At600DpiIsTheScreenImageEnlarged) {
    const auto dir = test::temp_dir("cli-print-a3");
    const std::string screen = (dir / "screen.png").string(), mask = (dir / "mask.png").string(),
                      poster = (dir / "poster.png").string();
    run_ok({"render", "--width", "554", "--height", "800", "-o", screen, "--mask", mask});
    const test::CommandResult r =
        test::run_stipple({"render", "--page", "A3", "--dpi", "600", "--height", "800", "--fit", "frame", "-o", poster});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("7016x9921"), std::string::npos) << r.out;
    const Image page = read_png(poster);
    ASSERT_EQ(page.width, 7016);
    ASSERT_EQ(page.height, 9921);
    const int margin = int(std::lround(10.0 * 600.0 / 25.4));
    const InkPair ink = ink_inside(read_png(screen), read_png(mask), page, margin);
    std::printf("mean ink inside the object: screen %.4f, A3 600 dpi downsampled %.4f (ratio %.3f)\n", ink.screen,
                ink.print, ink.print / ink.screen);
    EXPECT_GT(ink.screen, 0.05);
    EXPECT_NEAR(ink.print / ink.screen, 1.0, 0.05);
    // The margin stays paper.
    double margin_ink = 0.0;
    for (int x = 0; x < page.width; ++x) margin_ink += darkness(page, size_t(x), 3) + darkness(page, size_t(x), size_t(page.height - 3));
    EXPECT_EQ(margin_ink, 0.0);
}

// The box of the pixels darker than the paper in the drawing's room (the page less its margin), and their ink.
struct InkBox {
    int x0 = INT32_MAX, y0 = INT32_MAX, x1 = -1, y1 = -1;
    double ink = 0.0;
    int width() const { return x1 - x0 + 1; }
    int height() const { return y1 - y0 + 1; }
};
InkBox ink_box(const Image& page, int margin_px) {
    InkBox box;
    for (int y = margin_px; y < page.height - margin_px; ++y)
        for (int x = margin_px; x < page.width - margin_px; ++x) {
            const double d = darkness(page, size_t(x), size_t(y));
            if (d <= 0.0) continue;
            box.ink += d;
            box.x0 = std::min(box.x0, x), box.y0 = std::min(box.y0, y), box.x1 = std::max(box.x1, x), box.y1 = std::max(box.y1, y);
        }
    return box;
}

// By default a print's drawing fills the room inside its margins, as vector output's does (--fit drawing): the
// screen frame's box of what it draws is enlarged, so the print holds the frame's stipples with every dot
// enlarged alike, the ink growing as the square of the enlargement; a bare named page is turned as the
// drawing is. Until 2026-12-05 the whole frame was printed: the default scene covered 0.80 of an A5's width.
TEST(CliPrint, TheDrawingFillsThePageUnlessTheFrameIsAsked) {
    const auto dir = test::temp_dir("cli-print-fit");
    const std::string fitted = (dir / "fitted.png").string(), frame = (dir / "frame.png").string(),
                      upright = (dir / "upright.png").string();
    // The default scene (the blobby surface, wider than tall) on A5 at 100 dpi, 10 mm margins: 504 x 748 px of room
    // upright, 748 x 504 turned; the screen frame 256 rows high.
    const test::CommandResult a = test::run_stipple({"render", "--page", "A5", "--dpi", "100", "--height", "256", "-o", fitted});
    ASSERT_EQ(a.exit_code, 0) << a.err;
    EXPECT_NE(a.out.find("(827x583, A5 landscape at 100 dpi, the drawing fitted to it)"), std::string::npos) << a.out;
    run_ok({"render", "--page", "A5", "--dpi", "100", "--height", "256", "--fit", "frame", "-o", frame});
    run_ok({"render", "--page", "A5-portrait", "--dpi", "100", "--height", "256", "-o", upright});
    const int margin = int(std::lround(10.0 * 100.0 / 25.4));
    const Image page = read_png(fitted), whole = read_png(frame), portrait = read_png(upright);
    ASSERT_EQ(page.width, 827);
    ASSERT_EQ(whole.width, 583);  // the frame keeps the page upright unless told
    ASSERT_EQ(portrait.width, 583);
    const InkBox f = ink_box(page, margin), w = ink_box(whole, margin), p = ink_box(portrait, margin);
    const double room_w = page.width - 2 * margin, room_h = page.height - 2 * margin;
    std::printf("fitted: %dx%d of %.0fx%.0f, ink %.0f; frame: %dx%d, ink %.0f; portrait fitted: %dx%d of %dx%d\n", f.width(),
                f.height(), room_w, room_h, f.ink, w.width(), w.height(), w.ink, p.width(), p.height(),
                portrait.width - 2 * margin, portrait.height - 2 * margin);
    // One side fills the room (to the pixel of the box's widening), the other fits in it, centred.
    EXPECT_GT(std::max(f.width() / room_w, f.height() / room_h), 0.98);
    EXPECT_LE(f.width(), room_w);
    EXPECT_LE(f.height(), room_h);
    EXPECT_NEAR(0.5 * (f.x0 + f.x1), 0.5 * (page.width - 1), 3.0);
    EXPECT_NEAR(0.5 * (f.y0 + f.y1), 0.5 * (page.height - 1), 3.0);
    // The frame leaves paper around the drawing.
    EXPECT_LT(std::max(w.width() / double(whole.width - 2 * margin), w.height() / double(whole.height - 2 * margin)), 0.9);
    EXPECT_GT(std::max(p.width() / double(portrait.width - 2 * margin), p.height() / double(portrait.height - 2 * margin)), 0.98);
    // Upright, the fitted print enlarges the same screen frame as the frame's: the same stipples, every dot enlarged
    // as the drawing is, so the ink grows as the square of the enlargement.
    const double enlargement = 0.5 * (double(p.width()) / w.width() + double(p.height()) / w.height());
    std::printf("upright, enlarged %.3f (width %.3f, height %.3f): ink ratio over its square %.3f\n", enlargement,
                double(p.width()) / w.width(), double(p.height()) / w.height(), p.ink / w.ink / (enlargement * enlargement));
    EXPECT_GT(enlargement, 1.1);
    EXPECT_NEAR(double(p.width()) / w.width(), double(p.height()) / w.height(), 0.02);
    EXPECT_NEAR(p.ink / w.ink / (enlargement * enlargement), 1.0, 0.03);
}

// A drawing the frame cuts (the camera turned toward one side of it) is centred on the page all the same: the
// room past the frame's edge is paper (the region drawn was kept inside the enlarged frame, which put the
// drawing against the margin, 0 px from it on one side and 175 on the other). And tiles far smaller than the
// enlarged dots' reach grow to hold their guard band: 64-px tiles drew cuts through 6-px dots enlarged 4 times.
TEST(CliPrint, AFittedDrawingIsCentredAndItsTilesHoldItsDots) {
    const auto dir = test::temp_dir("cli-print-centred");
    const std::string scene = (dir / "cut.json").string(), page = (dir / "cut.png").string();
    {
        std::ofstream out(scene);
        out << "{\"objects\": [{\"model\": \"" << test::source_path("assets/blobby.glb")
            << "\"}], \"camera\": {\"distance\": 0.6, \"target\": [0.9, 0, 0]}}\n";
    }
    run_ok({"render", scene, "--page", "A5-portrait", "--dpi", "80", "--height", "200", "-o", page});
    const Image cut = read_png(page);
    const int margin = int(std::lround(10.0 * 80.0 / 25.4));
    const InkBox box = ink_box(cut, margin);
    std::printf("cut drawing: ink over columns %d-%d of %d, rows %d-%d of %d\n", box.x0, box.x1, cut.width, box.y0, box.y1,
                cut.height);
    EXPECT_NEAR(0.5 * (box.x0 + box.x1), 0.5 * (cut.width - 1), 3.0);
    EXPECT_NEAR(0.5 * (box.y0 + box.y1), 0.5 * (cut.height - 1), 3.0);
    EXPECT_GT(box.x0, margin + 10) << "paper left of the cut drawing";

    // Dots of 6 px enlarged about 4 times at this scale: 64-px tiles against one piece.
    const std::vector<std::string> far = {"render", "--distance", "2.5", "--point-size", "6", "--page", "A5", "--dpi", "80",
                                          "--height", "200"};
    std::vector<std::string> one = far, small = far;
    one.insert(one.end(), {"-o", (dir / "one.png").string()});
    small.insert(small.end(), {"-o", (dir / "small.png").string(), "--tile", "64"});
    run_ok(one);
    run_ok(small);
    const Image a = read_png((dir / "one.png").string()), b = read_png((dir / "small.png").string());
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    size_t differing = 0, inked = 0;
    for (size_t i = 0; i < a.pixels.size(); i += 4) differing += std::abs(int(a.pixels[i]) - int(b.pixels[i])) > 2, inked += a.pixels[i] < 128;
    std::printf("64-px tiles: %zu of %zu inked pixels differ from one piece\n", differing, inked);
    EXPECT_GT(inked, 10000u);
    EXPECT_LE(double(differing), 0.001 * double(inked));
}

// --width gives the print's screen frame the shape of the screen image it should look like (it was refused, and the
// frame took the page's shape: a wide scene's side objects were cut where the screen image held them whole). Two
// blobbies side by side, close up, in a frame 2.5 times as wide as tall: with --fit frame the print is that screen
// image enlarged until it fits the room, centred, on a page turned as the frame is; fitted to its drawing, the
// drawing keeps the screen image's shape.
TEST(CliPrint, AScreenFramesShapeIsKeptWithItsWidth) {
    const auto dir = test::temp_dir("cli-print-width");
    const std::string scene = (dir / "pair.json").string(), screen = (dir / "screen.png").string(),
                      mask = (dir / "mask.png").string(), frame = (dir / "frame.png").string(), fitted = (dir / "fitted.png").string(),
                      page_shaped = (dir / "page_shaped.png").string();
    {
        std::ofstream out(scene);
        const std::string model = test::source_path("assets/blobby.glb");
        out << "{\"objects\": [{\"model\": \"" << model << "\", \"transform\": {\"translate\": [-1.6, 0, 0]}}, {\"model\": \"" << model
            << "\", \"transform\": {\"translate\": [1.6, 0, 0]}}], \"camera\": {\"distance\": 0.55}}\n";
    }
    const std::vector<std::string> shape = {"--width", "400", "--height", "160"};
    std::vector<std::string> a = {"render", scene, "-o", screen, "--mask", mask}, b = {"render", scene, "--page", "A5", "--dpi", "100", "--fit", "frame", "-o", frame},
                             c = {"render", scene, "--page", "A5", "--dpi", "100", "-o", fitted};
    for (auto* args : {&a, &b, &c}) args->insert(args->end(), shape.begin(), shape.end());
    run_ok(a);
    const test::CommandResult r = test::run_stipple(b);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("A5 landscape"), std::string::npos) << r.out;
    run_ok(c);
    run_ok({"render", scene, "--page", "A5", "--dpi", "100", "--height", "160", "-o", page_shaped});
    const Image s = read_png(screen), whole = read_png(frame), fit = read_png(fitted), old = read_png(page_shaped);
    ASSERT_EQ(whole.width, 827);
    const int margin = int(std::lround(10.0 * 100.0 / 25.4));
    const double room_w = whole.width - 2 * margin, room_h = whole.height - 2 * margin;
    const double scale = std::min(room_w / 400.0, room_h / 160.0);
    const int dw = int(std::lround(400 * scale)), dh = int(std::lround(160 * scale));
    const int x0 = margin + int(std::lround((room_w - dw) / 2)), y0 = margin + int(std::lround((room_h - dh) / 2));
    const InkPair ink = ink_inside(s, read_png(mask), whole, x0, y0, dw, dh);
    std::printf("the frame on the page: %dx%d at (%d, %d); mean ink inside the objects: screen %.4f, print %.4f\n", dw, dh, x0, y0,
                ink.screen, ink.print);
    EXPECT_GT(ink.screen, 0.05);
    EXPECT_NEAR(ink.print / ink.screen, 1.0, 0.05);
    // The drawing's box: on the screen, and on the fitted page (the same shape), where the page-shaped frame cuts it.
    const InkBox on_screen = ink_box(s, 0), on_page = ink_box(fit, margin), cut = ink_box(old, margin);
    const double screen_shape = double(on_screen.width()) / on_screen.height();
    std::printf("drawing's box width over height: screen %.3f, fitted print %.3f, page-shaped frame %.3f\n", screen_shape,
                double(on_page.width()) / on_page.height(), double(cut.width()) / cut.height());
    EXPECT_GT(on_screen.x0, 2) << "the screen image holds both objects whole";
    EXPECT_LT(on_screen.x1, s.width - 3);
    EXPECT_NEAR(double(on_page.width()) / on_page.height(), screen_shape, 0.03 * screen_shape);
    EXPECT_GT(std::max(on_page.width() / room_w, on_page.height() / room_h), 0.98);
}

// A print records its resolution (a pHYs chunk in pixels per metre), so that it prints at its page size;
// without it programs assume 72 or 96 dpi. Screen images record none.
TEST(CliPrint, APrintRecordsItsResolution) {
    const auto dir = test::temp_dir("cli-print-dpi");
    const std::string print = (dir / "print.png").string(), screen = (dir / "screen.png").string();
    run_ok({"render", "--page", "60x80mm", "--dpi", "150", "--height", "128", "-o", print});
    run_ok({"render", "--width", "64", "--height", "64", "-o", screen});
    auto chunk_at = [](const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        return std::make_pair(bytes, bytes.find("pHYs"));
    };
    const auto found = chunk_at(print);  // (clang 15 cannot capture a structured binding in the lambda below)
    const std::string& bytes = found.first;
    const size_t at = found.second;
    ASSERT_NE(at, std::string::npos) << "no pHYs chunk";
    auto word = [&](size_t i) {
        return uint32_t(uint8_t(bytes[i])) << 24 | uint32_t(uint8_t(bytes[i + 1])) << 16 | uint32_t(uint8_t(bytes[i + 2])) << 8 |
               uint32_t(uint8_t(bytes[i + 3]));
    };
    EXPECT_EQ(word(at - 4), 9u);                                   // the chunk's length
    EXPECT_EQ(word(at + 4), uint32_t(std::lround(150 / 0.0254)));  // 5906 pixels a metre
    EXPECT_EQ(word(at + 8), word(at + 4));
    EXPECT_EQ(bytes[at + 12], 1) << "the unit is the metre";
    EXPECT_LT(at, bytes.find("IDAT")) << "PNG wants pHYs before the image data";
    const Image image = read_png(print);  // still a PNG that reads
    EXPECT_GT(image.width, 0);
    EXPECT_EQ(chunk_at(screen).second, std::string::npos);
}

TEST(CliPrint, TilesJoinWithoutSeams) {
    const auto dir = test::temp_dir("cli-print-tiles");
    const std::string whole = (dir / "whole.png").string(), tiled = (dir / "tiled.png").string();
    // Dots about 7 pixels across at this detail (a 200-pixel screen drawing enlarged to ~1500, and the drawing's
    // box to the page, turned): with tiles that did not overlap, a dot astride a tile edge whose centre lay in the
    // next tile was cut off.
    const std::vector<std::string> common = {"render", "--page", "A5", "--dpi", "200", "--height", "200", "--yaw", "30"};
    std::vector<std::string> a = common, b = common;
    a.insert(a.end(), {"-o", whole});
    b.insert(b.end(), {"-o", tiled, "--tile", "300"});  // a 1496 x 1008-pixel room: 7 x 5 tiles of 300 with their guard bands
    run_ok(a);
    run_ok(b);
    const Image one = read_png(whole), many = read_png(tiled);
    ASSERT_EQ(one.width, many.width);
    ASSERT_EQ(one.height, many.height);
    size_t differing = 0, inked = 0;
    for (size_t i = 0; i < one.pixels.size(); i += 4) {
        differing += std::abs(int(one.pixels[i]) - int(many.pixels[i])) > 2;
        inked += one.pixels[i] < 128;
    }
    std::printf("%zu of %zu pixels differ between one piece and 300-px tiles (%zu inked)\n", differing,
                one.pixels.size() / 4, inked);
    EXPECT_GT(inked, 10000u);
    EXPECT_LE(double(differing), 0.0001 * double(inked));
}

// The count `render --stats` prints after `label`; -1 without one.
long printed_count(const test::CommandResult& r, const std::string& label) {
    const size_t at = r.out.find(label);
    return at == std::string::npos ? -1 : std::stol(r.out.substr(at + label.size()));
}

// A print is drawn by a renderer of its own: --stats reports that renderer's figures (until 2026-12-02 it
// printed the unused screen renderer's: 0 triangles, 0 candidates, -1 drawn). Its drawn stipples are
// the screen image's at the same aspect and --height, since the print enlarges that image.
TEST(CliPrint, StatsAreThePrintsOwn) {
    const auto dir = test::temp_dir("cli-print-stats");
    // An A6 page (105 x 148 mm) at 100 dpi, 10 mm margins: a drawing of 85 x 128 mm, 335 x 505 px; the screen image at its aspect.
    const test::CommandResult page = test::run_stipple(
        {"render", "--page", "105x148mm", "--dpi", "100", "--height", "640", "--stats", "-o", (dir / "page.png").string()});
    ASSERT_EQ(page.exit_code, 0) << page.err;
    const test::CommandResult screen = test::run_stipple(
        {"render", "--width", "425", "--height", "640", "--stats", "-o", (dir / "screen.png").string()});
    ASSERT_EQ(screen.exit_code, 0) << screen.err;
    std::printf("print: %ld triangles, %ld candidates, %ld drawn; screen: %ld drawn\n",
                printed_count(page, "triangles:"), printed_count(page, "candidate stipples:"),
                printed_count(page, "drawn stipples:"), printed_count(screen, "drawn stipples:"));
    EXPECT_EQ(printed_count(page, "triangles:"), printed_count(screen, "triangles:"));
    EXPECT_GT(printed_count(page, "triangles:"), 1000);
    EXPECT_EQ(printed_count(page, "candidate stipples:"), printed_count(screen, "candidate stipples:"));
    const long drawn = printed_count(page, "drawn stipples:"), drawn_screen = printed_count(screen, "drawn stipples:");
    ASSERT_GT(drawn_screen, 10000);
    EXPECT_NEAR(double(drawn) / double(drawn_screen), 1.0, 0.02);
    EXPECT_NE(page.out.find("covered pixels:     not measured (drawn in tiles)"), std::string::npos) << page.out;
}

// A sequence of prints says what each file is: the page's pixels (it said the screen's 1280x1024).
TEST(CliPrint, ASequenceNamesItsPages) {
    const auto dir = test::temp_dir("cli-print-frames");
    const test::CommandResult r = test::run_stipple({"render", "--page", "A5", "--dpi", "50", "--frames", "2", "--orbit", "90",
                                                     "-o", (dir / "page%02d.png").string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("(291x413, A5 at 50 dpi, the frame's view)"), std::string::npos) << r.out;
    EXPECT_EQ(read_png((dir / "page01.png").string()).width, 291);
}

TEST(CliPrint, OptionsOutOfRangeAreNamed) {
    for (const auto& [args, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--dpi", "30", "--page", "A4"}, "--dpi = 30"},
             {{"--dpi", "300"}, "--dpi needs --page"},
             {{"--tile", "512"}, "--tile is for print-resolution images"},
             {{"--dpi", "2400", "--page", "5000x5000mm"}, "at most 65536 a side"}}) {
        std::vector<std::string> argv = {"render", "-o", (test::temp_dir("cli-print-bad") / "x.png").string()};
        argv.insert(argv.end(), args.begin(), args.end());
        const test::CommandResult r = test::run_stipple(argv);
        EXPECT_NE(r.exit_code, 0);
        EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    }
}

}  // namespace
}  // namespace stipple
