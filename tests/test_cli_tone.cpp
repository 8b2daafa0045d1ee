// `stipple tone` as a user runs it (issue 18: a command that prints the tone table for any model): the
// table's rows and figures, the seeds averaged with --seeds, and one-line refusals of bad options.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

// The rows of the table that start with "| on " or "| off": the cells between the bars, trimmed.
std::vector<std::vector<std::string>> rows(const std::string& out, const std::string& extrinsic) {
    std::vector<std::vector<std::string>> found;
    std::istringstream lines(out);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("| " + extrinsic + " ", 0) != 0) continue;
        std::vector<std::string> cells;
        std::istringstream parts(line.substr(1));
        std::string cell;
        while (std::getline(parts, cell, '|')) {
            const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
            cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
        }
        found.push_back(cells);
    }
    return found;
}

// The default scene, small and quick: two distances, two views, two frames each.
std::vector<std::string> quick(std::vector<std::string> extra) {
    std::vector<std::string> args{"tone", "--distances", "1,4", "--views", "30:10,30:-15", "--frames", "2", "--width", "320",
                                  "--height", "256"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

TEST(CliTone, PrintsTheInkPerDistanceAndItsMaxOverMin) {
    // --images makes its folder, as -o does.
    const std::filesystem::path images = test::temp_dir("cli-tone-images") / "made" / "here";
    const test::CommandResult r = test::run_stipple(quick({"--images", images.string()}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(std::filesystem::is_regular_file(images / "tone-30_10-d4-on.png")) << r.out;
    const auto on = rows(r.out, "on"), off = rows(r.out, "off");
    ASSERT_EQ(on.size(), 2u) << r.out;  // one row per view
    ASSERT_EQ(off.size(), 2u) << r.out;
    for (const auto& row : on) {
        ASSERT_EQ(row.size(), 5u) << r.out;  // extrinsic, view, d=1, d=4, max/min
        const double near = std::stod(row[2]), far = std::stod(row[3]), figure = std::stod(row[4]);
        EXPECT_GT(near, 0.1);
        EXPECT_NEAR(figure, std::max(near, far) / std::min(near, far), 0.002);
        // 1.100 on the second view with solid dots, 1.094 with faint ones: 320 x 256 and two frames are few dots.
        EXPECT_LT(figure, 1.12) << "the enhancement keeps the tone";
    }
    for (const auto& row : off) EXPECT_GT(std::stod(row[3]), std::stod(row[2])) << "without it, far reads darker";
}

// Close up, `--regimes` tallies the polygons wholly outside the view apart, and its "all" row holds those in
// view: counted with them (until 2026-12-05), the owed ink per covered pixel read 6 times too high on the
// bunny at a quarter of its distance.
TEST(CliTone, RegimesTallyThePolygonsOutsideTheViewApart) {
    const test::CommandResult r =
        test::run_stipple({"tone", "--distances", "0.3,1", "--regimes", "--width", "320", "--height", "256"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // "| 0.3 | outside the view | POLYGONS |" and "| 0.3 | all | POLYGONS |", and the same at d = 1.
    auto polygons = [&](const std::string& distance, const std::string& regime) -> long {
        const std::string key = "| " + distance + " | " + regime + " | ";
        const size_t at = r.out.find(key);
        return at == std::string::npos ? -1 : std::stol(r.out.substr(at + key.size()));
    };
    const long outside = polygons("0.3", "outside the view"), in_view = polygons("0.3", "all");
    std::printf("at d=0.3: %ld polygons outside the view, %ld in it; framed: %ld\n", outside, in_view, polygons("1", "all"));
    EXPECT_GT(outside, 1000);
    EXPECT_EQ(outside + in_view, 40240) << "the default scene's polygons, each tallied once";
    EXPECT_EQ(polygons("1", "outside the view"), -1) << "framed, none lies outside";
    EXPECT_EQ(polygons("1", "all"), 40240);
}

// A two-sided object's back faces, seen from inside, draw: `--regimes` tallies them by their regime, not as
// culled, so the regimes add up to its "all" row (they owed 271k stipples in "all" and 22.5k in the rows of an
// open hemisphere seen from below, until 2026-12-06). Here the default scene, two-sided, seen from behind and
// below, with the same sum checked on every distance.
TEST(CliTone, RegimesOfATwoSidedObjectAddUp) {
    const test::CommandResult r = test::run_stipple({"tone", "--two-sided", "--regimes", "--distances", "1,8", "--views",
                                                     "200:-40", "--width", "320", "--height", "256"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const std::string distance : {"1", "8"}) {
        double regimes = 0.0, all = 0.0;
        std::istringstream lines(r.out);
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("| " + distance + " | ", 0) != 0) continue;
            std::vector<std::string> cells;  // distance, regime, polygons, owed, ... (the ink table's second cell is a number)
            std::istringstream parts(line.substr(1));
            for (std::string cell; std::getline(parts, cell, '|');) cells.push_back(cell);
            if (cells.size() < 4 || std::none_of(cells[1].begin(), cells[1].end(), [](char c) { return std::isalpha(c); })) continue;
            (cells[1].find(" all ") != std::string::npos ? all : regimes) += std::stod(cells[3]);
        }
        std::printf("d=%s: the regimes owe %.1f, all %.1f\n", distance.c_str(), regimes, all);
        ASSERT_GT(all, 0.0) << r.out;
        EXPECT_NEAR(regimes, all, 0.001 * all + 0.5) << r.out;
    }
}

// A distance where the object covers nothing has no tone: it shows as "-", is left out of max/min (which
// was 0.000 or not, by the order of --distances, until 2026-12-04) and is warned about.
TEST(CliTone, ADistanceThatCoversNothingIsLeftOutOfMaxOverMin) {
    for (const std::string distances : {"1,2,300", "300,1,2"}) {
        const test::CommandResult r = test::run_stipple(
            {"tone", "--distances", distances, "--views", "30:10", "--width", "96", "--height", "80"});
        ASSERT_EQ(r.exit_code, 0) << r.err;
        EXPECT_NE(r.err.find("at d=300 the object covers no pixel or inks none in view 30:10"), std::string::npos) << r.err;
        const auto on = rows(r.out, "on");
        ASSERT_EQ(on.size(), 1u) << r.out;
        ASSERT_EQ(on[0].size(), 6u) << r.out;
        const size_t far = distances == "1,2,300" ? 4 : 2;
        EXPECT_EQ(on[0][far], "-") << r.out;
        const double a = std::stod(on[0][far == 4 ? 2 : 3]), b = std::stod(on[0][far == 4 ? 3 : 4]);
        EXPECT_NEAR(std::stod(on[0][5]), std::max(a, b) / std::min(a, b), 0.002) << r.out;
    }
}

// A figure from few dots is mostly sampling noise: the command says so, with the dots it rests on and
// 1/sqrt of them, where that exceeds 2.5%, and stays quiet where the object fills the frame.
TEST(CliTone, SaysWhereAFigureRestsOnTooFewDots) {
    const test::CommandResult small = test::run_stipple(
        {"tone", "--distances", "1,16", "--views", "30:10", "--width", "320", "--height", "256"});
    ASSERT_EQ(small.exit_code, 0) << small.err;
    const size_t at = small.out.find("Sampling: at d=16 a view's figure rests on about ");
    ASSERT_NE(at, std::string::npos) << small.out;
    double dots = 0.0, spread = 0.0;
    ASSERT_EQ(std::sscanf(small.out.c_str() + at, "Sampling: at d=16 a view's figure rests on about %lf dots", &dots), 1);
    const size_t by = small.out.find("by about +-", at);
    ASSERT_NE(by, std::string::npos);
    ASSERT_EQ(std::sscanf(small.out.c_str() + by, "by about +-%lf%%", &spread), 1);
    // Not called a bound where few polygons draw the dots (a polygon's dots come and go together).
    EXPECT_NE(small.out.find("more where few polygons draw them", at), std::string::npos) << small.out;
    EXPECT_GT(dots, 1.0);
    EXPECT_LT(dots, 1600.0) << "a 16-pixel-tall object";
    // The dots are printed rounded to a whole one, the spread to a tenth of a percent.
    EXPECT_GE(spread, 100.0 / std::sqrt(dots + 0.5) - 0.05);
    EXPECT_LE(spread, 100.0 / std::sqrt(std::max(dots - 0.5, 1.0)) + 0.05);

    const test::CommandResult full = test::run_stipple({"tone", "--distances", "1", "--views", "30:10"});
    ASSERT_EQ(full.exit_code, 0) << full.err;
    EXPECT_EQ(full.out.find("Sampling:"), std::string::npos) << "the framed object draws thousands of dots\n" << full.out;
}

TEST(CliTone, SeedsAreDrawnOneByOneAndAveraged) {
    const test::CommandResult r = test::run_stipple(quick({"--seeds", "1,2,3"}));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto on = rows(r.out, "on");
    // Per view: one row per seed, the averaged row and the mean of the seeds' figures.
    ASSERT_EQ(on.size(), 10u) << r.out;
    for (size_t view = 0; view < 2; ++view) {
        double sum_near = 0.0, sum_far = 0.0, sum_figures = 0.0;
        std::vector<std::string> seen;
        for (size_t seed = 0; seed < 3; ++seed) {
            const auto& row = on[2 * seed + view];
            seen.push_back(row[2]);
            sum_near += std::stod(row[3]);
            sum_far += std::stod(row[4]);
            sum_figures += std::stod(row[5]);
        }
        EXPECT_EQ(seen, (std::vector<std::string>{"1", "2", "3"}));
        const auto& mean = on[6 + view];
        EXPECT_EQ(mean[2], "mean");
        EXPECT_NEAR(std::stod(mean[3]), sum_near / 3.0, 1e-4);
        EXPECT_NEAR(std::stod(mean[4]), sum_far / 3.0, 1e-4);
        EXPECT_NEAR(std::stod(on[8 + view].back()), sum_figures / 3.0, 0.001);
    }
    // Other seeds draw other stipples: the seeds' rows are not all the same.
    EXPECT_NE(on[0][4], on[2][4]);
}

TEST(CliTone, BadOptionsGetOneLine) {
    for (const auto& [args, message] : std::vector<std::pair<std::vector<std::string>, std::string>>{
             {{"--seeds", "1,x"}, "stipple: --seeds: 'x' is not a finite number\n"},
             {{"--seeds", "1.5"}, "stipple: --seeds: '1.5' is not a whole number in [0, 4294967295]\n"},
             {{"--seed", "2", "--seeds", "1,2"}, "stipple: give --seed or --seeds, not both\n"},
             {{"--distances", "0"}, "stipple: --distances: 0 must be in [0.0001, 10000]\n"},
             {{"--views", "30"}, "stipple: --views: '30' is not YAW:PITCH (degrees)\n"},
             // Repeats drew a column or a seed's table twice (the seed averaged in twice) until 2026-12-07.
             {{"--distances", "1,1.0,2"},
              "stipple: --distances: '1.0' is the same distance as an earlier one, as the table names them\n"},
             {{"--seeds", "1,2,1"}, "stipple: --seeds: '1' is named twice (its table would be averaged in twice)\n"},
             {{"--images", "/proc/stipple-tone-images"},
              "stipple: --images /proc/stipple-tone-images: cannot make the folder (No such file or directory)\n"}}) {
        std::vector<std::string> argv{"tone"};
        argv.insert(argv.end(), args.begin(), args.end());
        const test::CommandResult r = test::run_stipple(argv);
        EXPECT_EQ(r.exit_code, 1) << args[0];
        EXPECT_EQ(r.err, message);
    }
}

// A validation message fails every command, not only render and view: tone exited 0 after printing 206 of
// them. The layer's best-practices checks are a message a run can always provoke (one about the debug
// extension a validated instance enables, at least).
TEST(CliTone, AValidationMessageFailsTheSurvey) {
    test::ScopedEnv validation("STIPPLE_VALIDATION", "1");
    test::ScopedEnv best_practices("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT");
    const test::CommandResult r = test::run_stipple(
        {"tone", "--distances", "1", "--views", "30:10", "--frames", "1", "--width", "160", "--height", "128"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("vulkan validation: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("Vulkan validation message(s): the result is not trustworthy"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("| on "), std::string::npos) << r.out;  // the survey itself ran
}

}  // namespace
}  // namespace stipple
