// The benchmark (issue 6): the model set has Table 1's polygon counts (derived deterministically from
// the scans, or procedural spheres without them), the mesh operations behind it, the report writers,
// and `stipple bench --quick` end to end (its figures are printed, never asserted against time).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bench/bench_compare.hpp"
#include "bench/bench_output.hpp"
#include "bench/bench_runner.hpp"
#include "mesh/mesh_ops.hpp"
#include "mesh/orientation.hpp"
#include "mesh/ply_writer.hpp"
#include "bench/model_set.hpp"
#include "bench/table1.hpp"
#include "cli/cmd_bench_plot.hpp"
#include "core/error.hpp"
#include "mesh/load_mesh.hpp"
#include "mesh/primitives.hpp"
#include "support/model_files.hpp"
#include "support/run_command.hpp"
#include "support/test_paths.hpp"

namespace stipple {
namespace {

namespace fs = std::filesystem;
using test::run_stipple;

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

bool have_scans() { return bench::scans_available(bench::ModelSetOptions::default_models_dir()); }

#define SKIP_WITHOUT_SCANS()                                                                            \
    do {                                                                                                \
        if (!have_scans())                                                                              \
            GTEST_SKIP() << "the scanned models are not in "                                            \
                         << bench::ModelSetOptions::default_models_dir().string()                      \
                         << " (horse.ply, igea.ply, stanford-bunny.obj, ogre.obj): skipping";         \
    } while (0)

// --- mesh operations -----------------------------------------------------------------------------

TEST(BenchMesh, MidpointSubdivisionQuadruplesAndWeldsMidpoints) {
    Mesh sphere = weld_positions(make_icosphere(2));  // closed: V - E + F = 2
    size_t v = sphere.vertex_count(), f = sphere.triangle_count(), e = f * 3 / 2;
    Mesh fine = subdivide_midpoints(sphere);
    EXPECT_EQ(fine.triangle_count(), 4 * f);
    EXPECT_EQ(fine.vertex_count(), v + e);  // one vertex per edge: shared midpoints are welded
    EXPECT_NEAR(total_area(fine), total_area(sphere), 1e-4 * total_area(sphere));  // flat split: same surface
    EXPECT_NO_THROW(validate_mesh(fine));
}

TEST(BenchMesh, WeldingMergesVerticesAtTheSamePosition) {
    Mesh soup;
    soup.source = "soup";
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    soup.indices = {0, 1, 2, 3, 4, 5};
    compute_vertex_normals(soup);
    Mesh welded = weld_positions(soup);
    EXPECT_EQ(welded.vertex_count(), 4u);
    EXPECT_EQ(welded.triangle_count(), 2u);
    EXPECT_EQ(welded.indices[1], welded.indices[3]);  // the shared edge's ends are one vertex each
    EXPECT_EQ(welded.indices[2], welded.indices[5]);
}

TEST(BenchMesh, SimplificationHitsTheTargetWithinTolerance) {
    Mesh sphere = weld_positions(make_uv_sphere(40'000));
    for (size_t target : {20'000u, 7'321u, 1'000u}) {
        SimplifyResult r = simplify_to(sphere, target, 0.02);
        std::printf("%zu -> %zu triangles (target %zu) by %s\n", sphere.triangle_count(), r.mesh.triangle_count(),
                    target, r.method.c_str());
        EXPECT_TRUE(within(r.mesh.triangle_count(), target, 0.02)) << r.mesh.triangle_count();
        EXPECT_NO_THROW(validate_mesh(r.mesh));
    }
    EXPECT_THROW(simplify_to(sphere, 100'000, 0.02), Error);  // cannot simplify upward
}

TEST(BenchMesh, InsideOutMeshesAreTurnedOutward) {
    Mesh sphere = make_icosphere(2);
    EXPECT_GT(signed_volume(sphere), 0.0);
    EXPECT_EQ(orient_consistently(sphere).triangles_turned, 0u);
    for (size_t t = 0; t < sphere.triangle_count(); ++t) std::swap(sphere.indices[3 * t + 1], sphere.indices[3 * t + 2]);
    EXPECT_LT(signed_volume(sphere), 0.0);
    EXPECT_EQ(orient_consistently(sphere).parts_turned_outward, 1u);
    EXPECT_NEAR(signed_volume(sphere), 4.0 / 3.0 * 3.14159265, 0.2);  // inscribed: a little less than the ball
}

TEST(BenchMesh, BinaryPlyRoundTrips) {
    Mesh sphere = weld_positions(make_uv_sphere(2'000));
    fs::path path = test::temp_dir("bench_ply") / "sphere.ply";
    write_ply_binary(path.string(), sphere);
    Mesh back = load_mesh(path.string());
    ASSERT_EQ(back.vertex_count(), sphere.vertex_count());
    EXPECT_EQ(back.indices, sphere.indices);
    for (size_t i = 0; i < sphere.vertex_count(); ++i) EXPECT_EQ(back.positions[i], sphere.positions[i]);
    EXPECT_THROW(write_ply_binary("/proc/no/such/folder/x.ply", sphere), Error);
}

// --- the model set -----------------------------------------------------------------------------

TEST(ModelSet, EveryRowHasItsPolygonCountWithinTwoPercent) {
    SKIP_WITHOUT_SCANS();
    bench::ModelSetOptions options;  // the build's cache: derived once, reused by later runs and the bench
    options.log = [](const std::string& line) { std::printf("%s\n", line.c_str()); };
    std::vector<bench::ModelEntry> entries = bench::prepare_model_set(options);
    ASSERT_EQ(entries.size(), bench::kPaperTable.size());
    const std::string build = fs::path(STIPPLE_SHADER_DIR).parent_path().string() + "/";
    const std::string cache = options.cache_dir.string() + "/";
    EXPECT_TRUE(cache.rfind(build, 0) == 0 || cache.rfind(std::string(STIPPLE_SOURCE_DIR) + "/", 0) != 0)
        << "the model cache " << cache << " is inside the sources but not in the build folder";
    for (size_t i = 0; i < entries.size(); ++i) {
        const bench::ModelEntry& e = entries[i];
        EXPECT_EQ(e.name, bench::kPaperTable[i].name);
        EXPECT_FALSE(e.procedural) << e.name;
        Mesh mesh = bench::load_model(e);  // the file on disk, not just the key's figure
        std::printf("%-15s %8zu triangles, row %8zu (%+.3f%%): %s\n", e.name.c_str(), mesh.triangle_count(), e.target,
                    100.0 * (double(mesh.triangle_count()) - double(e.target)) / double(e.target), e.source.c_str());
        EXPECT_EQ(mesh.triangle_count(), e.triangles) << e.name;
        EXPECT_TRUE(within(mesh.triangle_count(), bench::kPaperTable[i].polygons, 0.02))
            << e.name << ": " << mesh.triangle_count() << " triangles against the row's " << bench::kPaperTable[i].polygons;
        EXPECT_GT(signed_volume(mesh), 0.0) << e.name << " is inside out";
        if (e.name == "bunny") {
            EXPECT_EQ(mesh.triangle_count(), 69'451u);  // exactly the paper's bunny
            EXPECT_EQ(e.path.filename(), "stanford-bunny.obj");
        }
        if (e.name == "skeleton1") {
            EXPECT_EQ(e.path.filename(), "ogre.obj");  // 124,008: used as is
        }
        // Derived files live in the cache (the build folder's, or $STIPPLE_CACHE_DIR's), never in the sources.
        if (e.path.parent_path() != options.models_dir) {
            EXPECT_EQ(e.path.parent_path(), options.cache_dir) << e.path;
        }
    }
}

TEST(ModelSet, DerivationIsDeterministicAndCached) {
    SKIP_WITHOUT_SCANS();
    fs::path a = test::temp_dir("bench_models_a"), b = test::temp_dir("bench_models_b");
    bench::ModelSetOptions options;
    options.only = {"horse", "low-res dragon"};
    options.cache_dir = a;
    std::vector<bench::ModelEntry> first = bench::prepare_model_set(options);
    options.cache_dir = b;
    std::vector<bench::ModelEntry> second = bench::prepare_model_set(options);
    ASSERT_EQ(first.size(), 2u);
    for (size_t i = 0; i < first.size(); ++i) {
        EXPECT_TRUE(first[i].derived_now);
        EXPECT_EQ(read_bytes(first[i].path), read_bytes(second[i].path)) << first[i].name << " differs between runs";
    }
    // Again into the same folder: taken from the cache, not derived.
    options.cache_dir = a;
    auto stamp = fs::last_write_time(first[0].path);
    std::vector<bench::ModelEntry> again = bench::prepare_model_set(options);
    EXPECT_FALSE(again[0].derived_now);
    EXPECT_EQ(again[0].triangles, first[0].triangles);
    EXPECT_EQ(fs::last_write_time(first[0].path), stamp);
    // A damaged key (as after a source change) makes it derive again.
    std::ofstream(a / "horse.key") << "stipple bench model v0\n";
    EXPECT_TRUE(bench::prepare_model_set(options)[0].derived_now);
    // So does a derived model cut short in the cache, when the bench loads it (it failed the run until
    // 2026-12-07, where a damaged stipple cache entry is made again).
    std::vector<bench::ModelEntry> cut = bench::prepare_model_set(options);
    ASSERT_EQ(cut[0].path.parent_path(), a);
    fs::resize_file(cut[0].path, fs::file_size(cut[0].path) / 2);
    EXPECT_THROW(bench::load_model(cut[0]), Error);
    std::string said;
    options.log = [&](const std::string& line) { said += line + "\n"; };
    options.cache_dir = a.string() + "/";  // the folder however written (with a trailing slash it was not derived again)
    const Mesh mesh = bench::load_model(cut[0], options);
    EXPECT_EQ(mesh.triangle_count(), first[0].triangles);
    EXPECT_TRUE(cut[0].derived_now);
    EXPECT_NE(said.find("deriving it again"), std::string::npos) << said;
    EXPECT_EQ(read_bytes(cut[0].path), read_bytes(second[0].path));  // as derived into the other folder
}

// A run of chosen rows needs only their scans: --models horse with horse.ply alone was reported as
// procedural spheres throughout.
TEST(ModelSet, ScansAreLookedForOnlyForTheRowsRun) {
    const std::filesystem::path dir = test::temp_dir("bench_partial_scans");
    std::ofstream(dir / "horse.ply") << "ply\n";
    EXPECT_TRUE(bench::scans_available(dir, {"horse"}));
    EXPECT_FALSE(bench::scans_available(dir));
    EXPECT_FALSE(bench::scans_available(dir, {"horse", "bunny"}));
}

TEST(ModelSet, WithoutScansEveryRowIsAProceduralSphere) {
    bench::ModelSetOptions options;
    options.models_dir = "/nonexistent/stipple/models";
    options.cache_dir = test::temp_dir("bench_models_none");
    EXPECT_FALSE(bench::scans_available(options.models_dir));
    std::vector<bench::ModelEntry> entries = bench::prepare_model_set(options);
    ASSERT_EQ(entries.size(), bench::kPaperTable.size());
    for (const bench::ModelEntry& e : entries) {
        EXPECT_TRUE(e.procedural);
        EXPECT_NE(e.source.find("procedural"), std::string::npos) << e.source;
        EXPECT_TRUE(within(e.triangles, e.target, 0.02)) << e.name << ": " << e.triangles;
    }
    EXPECT_EQ(bench::load_model(entries[0]).triangle_count(), entries[0].triangles);
    EXPECT_TRUE(fs::is_empty(options.cache_dir));  // nothing written for spheres
    options.only = {"no such model"};
    EXPECT_THROW(bench::prepare_model_set(options), Error);
}

// --- the report writers ------------------------------------------------------------------------

bench::BenchResults synthetic_results() {
    bench::BenchResults r;
    r.device = "test device";
    r.width = 1280;
    r.height = 1024;
    r.frames = 20;
    r.warmup = 3;
    r.scans_found = true;
    r.columns = bench::make_columns({DensityPath::Vertex, DensityPath::Cpu, DensityPath::Indirect});
    for (const char* name : {"horse", "dragon"}) {
        bench::ModelResult m;
        m.entry.name = name;
        m.entry.target = bench::find_paper_row(name)->polygons;
        m.entry.triangles = m.entry.target;
        m.entry.source = "test";
        m.candidates = 1000;
        m.gpu_bytes = 20000;
        m.mesh_bytes = 4000;
        for (const bench::Column& c : r.columns) {
            bench::CellResult cell;
            cell.column = c;
            cell.paper_fps = bench::paper_fps(*bench::find_paper_row(name), c);
            // Exactly the paper's rate on the vertex path, half of it on the cpu path.
            cell.median_fps = *cell.paper_fps * (c.path == DensityPath::Vertex && !c.lines ? 1.0 : 0.5);
            cell.min_fps = cell.max_fps = cell.median_fps;
            cell.gpu_ms = {{"depth", 1.0}, {"stipples", 2.0}};
            cell.drawn = 500;
            m.cells.push_back(cell);
        }
        r.models.push_back(m);
    }
    return r;
}

TEST(BenchReport, MarkdownPutsThePapersFiguresAndRatiosBesideOurs) {
    std::string md = bench::markdown_report(synthetic_results());
    std::printf("%s", md.c_str());
    // Indirect computes the density on the GPU: compared with the paper's vertex-program column.
    EXPECT_NE(md.find("| horse | 13,352 | 13,352 | 60.4 / 60.39 = 1.00× | 30.2 / 60.39 = **0.50×** | "
                      "30.2 / 60.39 = **0.50×** |"),
              std::string::npos);
    // Table 1's layout: the fastest GPU-density path (vertex) and the only CPU one (cpu).
    EXPECT_NE(md.find("| horse | 60.4 / 60.39 = 1.00× (vertex) | 30.2 / 60.39 = **0.50×** (cpu) | "
                      "15.1 / 30.19 = **0.50×** (vertex) |"),
              std::string::npos);
    EXPECT_NE(md.find("| dragon | 871,414 | 871,414 | 2.99 / 2.99 = 1.00×"), std::string::npos);
    EXPECT_NE(md.find("| vertex + lines |"), std::string::npos);  // the column header
    EXPECT_NE(md.find("20.0 (16.0)"), std::string::npos);         // bytes per candidate, all (without mesh)
    EXPECT_EQ(md.find("machine's limit"), std::string::npos);     // no probe, no section
    bench::BenchResults with_probe = synthetic_results();
    with_probe.models[0].limit = bench::ModelResult::LimitProbe{900, 100, 2.0, 0.5};
    with_probe.models[0].limit->state_probe_ms = 1.6;
    const std::string probe_md = bench::markdown_report(with_probe);
    EXPECT_NE(probe_md.find("| horse | 900 | 100 | 2.00 | 0.50 | 4.00× | 1.60 | 1.25× | 2000, 500 |"), std::string::npos)
        << probe_md;
    nlohmann::json j = nlohmann::json::parse(bench::json_report(with_probe));
    EXPECT_DOUBLE_EQ(j["models"][0]["limit_probe"]["x_of_limit"].get<double>(), 4.0);
    EXPECT_DOUBLE_EQ(j["models"][0]["limit_probe"]["x_of_state_limit"].get<double>(), 1.25);
    EXPECT_TRUE(j["models"][1]["limit_probe"].is_null());
}

TEST(BenchReport, SplatAgainstThePointsPipelinePerDrawnStipple) {
    bench::BenchResults r = synthetic_results();
    EXPECT_EQ(bench::markdown_report(r).find("against the points pipeline"), std::string::npos);  // no splat column
    EXPECT_TRUE(nlohmann::json::parse(bench::json_report(r))["models"][0]["splat_against_points"].is_null());
    // The horse gets splat cells: its indirect cells draw in 2 ms (synthetic_results), the splat's dispatches
    // take 0.5 ms and its copies 0.25 + 0.2 + 0.05. The cell with lines must not count.
    for (const bool lines : {false, true}) {
        bench::CellResult splat;
        splat.column = bench::Column{DensityPath::Splat, lines};
        splat.gpu_ms = {{"depth", 1.0}, {"depth_copy", 0.25}, {"splat_in", 0.2}, {"splat", lines ? 9.0 : 0.5}, {"splat_out", 0.05}};
        r.models[0].cells.push_back(splat);
    }
    const std::string md = bench::markdown_report(r);
    EXPECT_NE(md.find("| horse | 2.00 | 0.50 | 4.00× | 1.00 | 2.00× |"), std::string::npos) << md;
    EXPECT_EQ(md.find("| dragon | 2.00 |"), std::string::npos);  // no splat cell, no row
    const nlohmann::json j = nlohmann::json::parse(bench::json_report(r));
    EXPECT_DOUBLE_EQ(j["models"][0]["splat_against_points"]["x"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(j["models"][0]["splat_against_points"]["x_kernel"].get<double>(), 4.0);
    EXPECT_TRUE(j["models"][1]["splat_against_points"].is_null());
}

TEST(BenchReport, JsonHoldsEveryCell) {
    nlohmann::json j = nlohmann::json::parse(bench::json_report(synthetic_results()));
    ASSERT_EQ(j["models"].size(), 2u);
    EXPECT_EQ(j["models"][0]["cells"].size(), 6u);
    EXPECT_EQ(j["paper_table"].size(), 7u);
    const auto& cell = j["models"][1]["cells"][1];  // dragon, cpu
    EXPECT_EQ(cell["path"], "cpu");
    EXPECT_EQ(cell["silhouettes"], "none");
    EXPECT_DOUBLE_EQ(cell["paper_fps"].get<double>(), 1.50);
    EXPECT_DOUBLE_EQ(cell["ratio_to_paper"].get<double>(), 0.5);
    EXPECT_DOUBLE_EQ(j["models"][1]["cells"][2]["paper_fps"].get<double>(), 2.99);  // indirect: GPU density
}

TEST(BenchReport, ChartHasAxesLegendAndOneSeriesPerColumn) {
    std::string svg = bench::svg_chart(synthetic_results());
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    auto count = [&](const std::string& what) {
        size_t n = 0;
        for (size_t at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1)) ++n;
        return n;
    };
    EXPECT_EQ(count("<polyline"), 6u + 4u);  // our 6 columns, the paper's 4
    EXPECT_EQ(count("stroke-dasharray"), 2u * 4u);  // the paper's series and their legend entries
    for (const char* label : {"ours: vertex", "ours: cpu + lines", "ours: indirect", "paper: vertex program",
                              "paper: no vertex program + lines", "frames per second", "polygons", ">10k<", ">1M<"})
        EXPECT_NE(svg.find(label), std::string::npos) << label;
}

// A run of every path with object lines has 29 series: the canvas grows so that the legend's last entry
// (the paper's) stays on it (it ran off the 600-px canvas until 2026-12-04), and each kind of line has its
// own marker (contours, borders and creases shared the silhouettes' square).
TEST(BenchReport, ChartOfEveryColumnKeepsItsLegendAndTellsTheLinesApart) {
    bench::BenchResults r = synthetic_results();
    r.columns = bench::make_columns(bench::all_density_paths(), true);
    for (bench::ModelResult& m : r.models) {
        m.cells.clear();
        for (const bench::Column& c : r.columns) {
            bench::CellResult cell;
            cell.column = c;
            cell.median_fps = cell.min_fps = cell.max_fps = 10.0;
            m.cells.push_back(cell);
        }
    }
    const std::string svg = bench::svg_chart(r);
    const size_t at = svg.find("height=\"") + 8;
    const double height = std::stod(svg.substr(at));
    const size_t last = svg.rfind("paper: no vertex program + lines");
    ASSERT_NE(last, std::string::npos);
    const size_t y_at = svg.rfind(" y=\"", last) + 4;
    EXPECT_LT(std::stod(svg.substr(y_at)), height - 4) << "the legend's last entry is below the canvas";
    // Triangles for contours, diamonds for borders, upside-down triangles for creases: 2 models x 5 paths
    // each, plus 5 legend entries each.
    auto count = [&](const std::string& what) {
        size_t n = 0;
        for (size_t i = svg.find(what); i != std::string::npos; i = svg.find(what, i + 1)) ++n;
        return n;
    };
    EXPECT_EQ(count("<polygon"), 3u * (2u * 5u + 5u));
}

// --- the regression guard (--compare) ----------------------------------------------------------

// Two results.json files: the new one has horse/vertex 15% slower, horse/cpu 5% slower (within the
// noise allowance), dragon/cpu + lines 30% faster, the dragon's generation at half its speed, and no
// dragon/indirect + lines cell; a model only the new run has.
TEST(BenchCompare, ListsCellsSlowerByMoreThanTenPercentAndMissingOnes) {
    bench::BenchResults old_run = synthetic_results();
    old_run.models[1].generation_seconds = 2.0;  // 1000 candidates: 500 a second
    bench::BenchResults new_run = old_run;
    auto cell = [&](size_t model, const std::string& column) -> bench::CellResult& {
        for (bench::CellResult& c : new_run.models[model].cells)
            if (c.column.name() == column) return c;
        throw std::runtime_error("no cell " + column);
    };
    cell(0, "vertex").median_fps *= 0.85;
    cell(0, "cpu").median_fps *= 0.95;
    cell(1, "cpu + lines").median_fps *= 1.3;
    new_run.models[1].generation_seconds = 4.0;
    auto& dragon_cells = new_run.models[1].cells;
    dragon_cells.erase(std::remove_if(dragon_cells.begin(), dragon_cells.end(),
                                      [](const bench::CellResult& c) { return c.column.name() == "indirect + lines"; }),
                       dragon_cells.end());
    new_run.models.push_back(new_run.models[0]);
    new_run.models.back().entry.name = "bunny";

    const auto old_speeds = bench::read_speeds(bench::json_report(old_run), "old.json");
    const auto new_speeds = bench::read_speeds(bench::json_report(new_run), "new.json");
    EXPECT_EQ(old_speeds.size(), 2u * 6u + 1u);  // 6 cells a model, the dragon's generation
    EXPECT_DOUBLE_EQ(old_speeds.at("dragon / generation"), 500.0);
    const bench::Comparison c = bench::compare_speeds(old_speeds, new_speeds);
    EXPECT_EQ(c.compared, 12u);  // 13 old keys but the dropped cell
    ASSERT_EQ(c.slower.size(), 2u);
    EXPECT_EQ(c.slower[0].key, "dragon / generation");  // worst first: half the speed
    EXPECT_NEAR(c.slower[0].loss(), 0.5, 1e-12);
    EXPECT_EQ(c.slower[1].key, "horse / vertex");
    EXPECT_NEAR(c.slower[1].loss(), 0.15, 1e-12);
    EXPECT_EQ(c.worst.key, "dragon / generation");
    EXPECT_EQ(c.only_in_old, std::vector<std::string>{"dragon / indirect + lines"});
    EXPECT_EQ(c.only_in_new.size(), 6u);  // the bunny's cells
    EXPECT_EQ(c.only_in_new.front().rfind("bunny / ", 0), 0u);

    const std::string text = bench::comparison_text(c, "old.json");
    std::printf("%s", text.c_str());
    EXPECT_NE(text.find("slower: horse / vertex -15.0% (60.39 -> 51.33)"), std::string::npos) << text;
    EXPECT_EQ(text.find("slower: horse / cpu "), std::string::npos) << "5% is within the allowance";
    EXPECT_NE(text.find("missing in this run: dragon / indirect + lines"), std::string::npos);
    EXPECT_NE(text.find("missing in old.json: bunny / vertex"), std::string::npos);
    EXPECT_NE(text.find("compared with old.json: 12 cells compared, 2 slower by more than 10%, the worst: dragon / "
                        "generation -50.0%"),
              std::string::npos)
        << text;
    // The same run against itself: nothing slower, nothing missing.
    const bench::Comparison same = bench::compare_speeds(old_speeds, old_speeds);
    EXPECT_EQ(same.compared, old_speeds.size());
    EXPECT_TRUE(same.slower.empty() && same.only_in_old.empty() && same.only_in_new.empty());
    EXPECT_DOUBLE_EQ(same.worst.loss(), 0.0);
}

// Runs made otherwise say so, and a model drawn from other geometry (a sphere standing in for a missing
// scan) is left out rather than reported 75% slower (both were compared silently until 2026-12-04).
TEST(BenchCompare, SaysHowTheRunsDifferAndLeavesOutModelsOfOtherGeometry) {
    const bench::BenchResults old_run = synthetic_results();
    bench::BenchResults new_run = old_run;
    new_run.width = 640;
    new_run.queued = 2;
    new_run.models[0].entry.source = "procedural sphere";
    for (bench::CellResult& c : new_run.models[0].cells) c.median_fps *= 0.25;
    const bench::Comparison c = bench::compare_runs(bench::json_report(old_run), "old.json", bench::json_report(new_run));
    EXPECT_EQ(c.settings, (std::vector<std::string>{"width 1280 -> 640", "queued_frames 1 -> 2"}));
    ASSERT_EQ(c.not_comparable.size(), 1u);
    EXPECT_EQ(c.not_comparable[0], "horse: test, 13352 triangles -> procedural sphere, 13352 triangles");
    EXPECT_TRUE(c.slower.empty());
    EXPECT_EQ(c.compared, 6u);  // the dragon's cells
    const std::string text = bench::comparison_text(c, "old.json");
    EXPECT_NE(text.find("made differently, so their speeds differ for that too: width 1280 -> 640; queued_frames 1 -> 2"),
              std::string::npos) << text;
    EXPECT_NE(text.find("not comparable (other geometry), left out: horse"), std::string::npos) << text;
    // The same run: nothing said.
    const bench::Comparison same = bench::compare_runs(bench::json_report(old_run), "old.json", bench::json_report(old_run));
    EXPECT_TRUE(same.settings.empty() && same.not_comparable.empty());
    // A folder is not a results file, nor a FIFO (read, it waited for a writer for ever).
    try {
        bench::read_results_file(test::temp_dir("bench_compare_folder").string());
        ADD_FAILURE() << "a folder was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
    }
    const std::string fifo = (test::temp_dir("bench_compare_fifo") / "results.json").string();
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    try {
        bench::read_results_file(fifo);
        ADD_FAILURE() << "a FIFO was read";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), fifo + ": is not a regular file: --compare takes an earlier run's results.json");
    }
    // A described field holding no plain value (here 100,000 nested arrays, which printing recursed through
    // until the stack overflowed) reads as absent: the model stays comparable.
    nlohmann::json deep_run = nlohmann::json::parse(bench::json_report(old_run));
    deep_run["models"][0]["triangles"] = "@";
    std::string deep_text = deep_run.dump();
    deep_text.replace(deep_text.find("\"@\""), 3, std::string(100000, '[') + std::string(100000, ']'));
    const bench::Comparison deep = bench::compare_runs(deep_text, "old.json", bench::json_report(old_run));
    EXPECT_TRUE(deep.not_comparable.empty());
    EXPECT_EQ(deep.compared, 12u);
    // The depth options and the plot order's dot count change the speeds too (they read as regressions).
    bench::BenchResults culled = old_run, more_dots = old_run;
    culled.depth_cull = "on";
    culled.depth_raster = "fixed";
    EXPECT_EQ(bench::compare_runs(bench::json_report(old_run), "old.json", bench::json_report(culled)).settings,
              (std::vector<std::string>{"depth_cull auto -> on", "depth_raster auto -> fixed"}));
    bench::BenchResults few_dots = old_run;
    few_dots.plot_order = bench::PlotOrderRow{};
    few_dots.plot_order->blue_noise = bench::PlotOrderFigures{1000, 0.001};
    more_dots.plot_order = bench::PlotOrderRow{};
    more_dots.plot_order->blue_noise = bench::PlotOrderFigures{40000, 0.08};
    const bench::Comparison dots = bench::compare_runs(bench::json_report(few_dots), "old.json", bench::json_report(more_dots));
    EXPECT_TRUE(dots.slower.empty());
    ASSERT_EQ(dots.not_comparable.size(), 1u);
    EXPECT_EQ(dots.not_comparable[0], "plot order / blue noise: 1000 -> 40000 dots");
    EXPECT_NE(bench::comparison_text(dots, "old.json").find("not comparable (other dot count), left out: plot order"),
              std::string::npos);
}

TEST(BenchCompare, MalformedOrMissingFilesFailWithOneLineNamingThem) {
    auto message = [](const std::string& text) {
        try {
            bench::read_speeds(text, "old/results.json");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    for (const std::string& text :
         {std::string("{ not json"), std::string("{}"), std::string("[1, 2]"), std::string(R"({"models": 3})"),
          std::string(R"({"models": [{"name": "horse", "cells": [{"column": "vertex", "median_fps": "fast"}]}]})"),
          std::string(R"({"models": [{"name": "horse", "cells": [{"median_fps": 3}]}]})")}) {
        const std::string m = message(text);
        EXPECT_EQ(m.rfind("old/results.json: ", 0), 0u) << text << " -> " << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
    EXPECT_NE(message(R"({"models": [{"name": "horse", "cells": [{"column": "vertex", "median_fps": "fast"}]}]})")
                  .find("median_fps"),
              std::string::npos);
    const std::string negative = R"({"models": [{"name": "horse", "cells": [{"column": "vertex", "median_fps": -5}],
                                      "preprocessing_seconds": 1, "candidate_stipples": 10}]})";
    EXPECT_EQ(message(negative), "old/results.json: \"horse / vertex\" has the speed -5; a speed cannot be negative");
    std::string zero = negative;
    zero.replace(zero.find("-5"), 2, "0");
    const auto speeds = bench::read_speeds(zero, "old/results.json");
    EXPECT_EQ(speeds.count("horse / vertex"), 0u) << "a cell that measured nothing is not compared";
    EXPECT_EQ(speeds.count("horse / generation"), 1u);
    try {
        bench::read_speeds_file("/nonexistent/old/results.json");
        ADD_FAILURE() << "a missing file was read";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/old/results.json: ", 0), 0u) << e.what();
    }
}

// --- the plot-order row ------------------------------------------------------------------------

TEST(BenchPlotOrder, BunnyViewIsOrderedWithinIssueFifteensRatio) {
    SKIP_WITHOUT_SCANS();
    const auto log = [](const std::string& line) { std::printf("%s\n", line.c_str()); };
    const bench::PlotOrderRow row =
        cli::measure_plot_order_row(2'000, true, bench::ModelSetOptions::default_models_dir(), 640, 512, -1, log);
    ASSERT_TRUE(row.blue_noise);
    EXPECT_NEAR(double(row.blue_noise->dots), 2'000, 200);
    EXPECT_GT(row.blue_noise->random_ratio, 5.0);
    ASSERT_TRUE(row.bunny_view) << row.bunny_note;
    EXPECT_GT(row.bunny_view->dots, 5'000u);  // the visible stipples of a 640x512 bunny
    EXPECT_GT(row.bunny_view->travel_ratio, 1.0);
    EXPECT_LT(row.bunny_view->travel_ratio, 1.6);  // issue 15: pen-up travel <= 1.6x its lower bound
    EXPECT_EQ(row.validation_messages, 0u);
    const std::string md = bench::plot_order_markdown(row);
    EXPECT_NE(md.find("| bunny, default view (captured in "), std::string::npos) << md;
}

TEST(BenchPlotOrder, WithoutTheScanTheBunnyIsLeftOutWithANote) {
    const bench::PlotOrderRow row =
        cli::measure_plot_order_row(1'000, true, "/nonexistent/stipple/models", 320, 256, -1, [](const std::string&) {});
    EXPECT_TRUE(row.blue_noise);
    EXPECT_FALSE(row.bunny_view);
    EXPECT_NE(row.bunny_note.find("/nonexistent/stipple/models/stanford-bunny.obj"), std::string::npos) << row.bunny_note;
    bench::BenchResults results = synthetic_results();
    results.plot_order = row;
    nlohmann::json j = nlohmann::json::parse(bench::json_report(results));
    EXPECT_TRUE(j["plot_order"]["bunny view"].is_null());
    EXPECT_EQ(j["plot_order"]["blue noise"]["dots"].get<size_t>(), row.blue_noise->dots);
    // The row's speed is a key of the regression guard.
    EXPECT_EQ(bench::read_speeds(bench::json_report(results), "r.json").count("plot order / blue noise"), 1u);
}

// --- stipple bench ----------------------------------------------------------------------------

// Results that cannot be written are said before the run, not after every frame has been timed.
TEST(BenchCommand, AnUnwritableResultIsRefusedBeforeTheRun) {
    const std::filesystem::path out = test::temp_dir("bench_unwritable");
    std::filesystem::create_directories(out / "results.json");  // a folder where the file goes
    test::CommandResult r = run_stipple({"bench", "--quick", "--out", out.string()});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(r.err, "stipple: " + (out / "results.json").string() + ": cannot be written: the results would be lost after the run\n");
    EXPECT_EQ(r.out, "") << "nothing was run";
}

TEST(BenchCommand, QuickRunWritesTableJsonAndChart) {
    fs::path out = test::temp_dir("bench_quick");
    test::CommandResult r = run_stipple({"bench", "--quick", "--out", out.string()});
    std::printf("%s", r.out.c_str());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* file : {"results.md", "results.json", "chart.svg"}) EXPECT_TRUE(fs::is_regular_file(out / file)) << file;
    nlohmann::json j = nlohmann::json::parse(read_bytes(out / "results.json"));
    EXPECT_EQ(j["validation_messages"], 0);
    EXPECT_EQ(j["queued_frames"], 1) << "a CPU device waits on every frame by default";
    EXPECT_EQ(j["width"], 1280);
    EXPECT_EQ(j["height"], 1024);
    ASSERT_EQ(j["models"].size(), 2u);
    EXPECT_EQ(j["models"][0]["name"], "horse");
    EXPECT_EQ(j["models"][1]["name"], "low-res dragon");
    for (const auto& model : j["models"]) {
        std::set<std::pair<std::string, std::string>> cells;
        for (const auto& cell : model["cells"]) {
            cells.insert({cell["path"].get<std::string>(), cell["silhouettes"].get<std::string>()});
            EXPECT_GT(cell["median_fps"].get<double>(), 0.0);
            EXPECT_GT(cell["drawn_stipples"].get<int64_t>(), 0);
            EXPECT_GT(cell["candidate_stipples"].get<int64_t>(), cell["drawn_stipples"].get<int64_t>());
            EXPECT_EQ(cell["frame_ms"].size(), 5u);
            EXPECT_FALSE(cell["gpu_ms"].empty());
            EXPECT_FALSE(cell["paper_fps"].is_null());
        }
        std::set<std::pair<std::string, std::string>> expected = {
            {"vertex", "none"}, {"cpu", "none"}, {"splat", "none"},
            {"vertex", "lines"}, {"cpu", "lines"}, {"splat", "lines"}};
        EXPECT_EQ(cells, expected) << model["name"];
        EXPECT_GT(model["drawn_stipples"].get<int64_t>(), 0);
        EXPECT_GT(model["ink_fraction"].get<double>(), 0.0);
        EXPECT_GT(model["gpu_bytes_per_candidate"].get<double>(), 0.0);
        EXPECT_EQ(model["procedural"].get<bool>(), !have_scans());
        EXPECT_TRUE(fs::is_regular_file(model["image"].get<std::string>()));
    }
    std::string md = read_bytes(out / "results.md");
    EXPECT_NE(md.find("| horse"), std::string::npos);
    EXPECT_NE(md.find("| low-res dragon"), std::string::npos);
    EXPECT_NE(r.out.find("## Frames per second"), std::string::npos);  // the table is printed too
    EXPECT_NE(read_bytes(out / "chart.svg").find("</svg>"), std::string::npos);
    // The animated row (issue 16): the skinned cylinder static and playing, its deformation timed.
    ASSERT_TRUE(j.contains("animated"));
    const nlohmann::json& a = j["animated"];
    EXPECT_GE(a["triangles"].get<uint64_t>(), 20000u);
    EXPECT_GT(a["deform_gpu_ms"].get<double>(), 0.0);
    EXPECT_GT(a["animated_gpu_ms"].get<double>(), a["deform_gpu_ms"].get<double>());
    EXPECT_GT(a["static_frame_ms"].get<double>(), 0.0);
    EXPECT_GT(a["animated_drawn"].get<int64_t>(), 0);
    EXPECT_GT(a["animated_candidates"].get<uint64_t>(), a["static_candidates"].get<uint64_t>()) << "stretch headroom";
    EXPECT_NE(md.find("## Animated row"), std::string::npos);
    // The limit probe: as many culled and drawn points as the vertex column (no lines) had.
    for (const auto& model : j["models"]) {
        const auto& limit = model["limit_probe"];
        ASSERT_TRUE(limit.is_object()) << model["name"];
        const nlohmann::json* vertex = nullptr;
        for (const auto& cell : model["cells"])
            if (cell["column"] == "vertex") vertex = &cell;
        ASSERT_NE(vertex, nullptr);
        EXPECT_EQ(limit["drawn_points"].get<int64_t>(), (*vertex)["drawn_stipples"].get<int64_t>());
        EXPECT_EQ(limit["culled_points"].get<int64_t>() + limit["drawn_points"].get<int64_t>(),
                  (*vertex)["candidate_stipples"].get<int64_t>());
        EXPECT_GT(limit["probe_ms"].get<double>(), 0.0);
        EXPECT_GT(limit["vertex_stipples_ms"].get<double>(), 0.0);
        EXPECT_DOUBLE_EQ(limit["x_of_limit"].get<double>(),
                         limit["vertex_stipples_ms"].get<double>() / limit["probe_ms"].get<double>());
        // The probe with the stipple pass's depth, stencil and blending: one timing per timed frame too.
        EXPECT_GT(limit["state_probe_ms"].get<double>(), 0.0);
        EXPECT_EQ(limit["state_probe_frame_ms"].size(), limit["probe_frame_ms"].size());
        EXPECT_DOUBLE_EQ(limit["x_of_state_limit"].get<double>(),
                         limit["vertex_stipples_ms"].get<double>() / limit["state_probe_ms"].get<double>());
    }
    EXPECT_NE(md.find("## The vertex path against the machine's limit"), std::string::npos);
    // The plot-order row, shrunk: 15k blue-noise dots, no bunny view.
    const auto& plot = j["plot_order"];
    ASSERT_TRUE(plot.is_object()) << plot.dump();
    const auto& blue = plot["blue noise"];
    EXPECT_NEAR(blue["dots"].get<double>(), 15'000, 1'500);
    EXPECT_GT(blue["travel_ratio"].get<double>(), 1.0);   // nothing beats the bound
    EXPECT_LT(blue["travel_ratio"].get<double>(), 1.6);   // issue 15's figure for a good order
    EXPECT_GT(blue["random_ratio"].get<double>(), 10.0);  // the bound is not trivially loose
    EXPECT_TRUE(plot["bunny view"].is_null());
    EXPECT_NE(md.find("## Plot order"), std::string::npos);
}

TEST(BenchCommand, WithoutScansItSaysSoAndUsesSpheres) {
    fs::path out = test::temp_dir("bench_no_scans");
    // A folder without the scans (one named that is not there is refused: BadArgumentsFailWithOneLine).
    const fs::path models = test::temp_dir("bench_no_scans_models") / "stipple's models";
    fs::create_directories(models);
    // Three frames queued per submission: every column's passes recorded back to back in one command
    // buffer (the validation layer is on: a descriptor set rewritten between them would be an error).
    test::CommandResult r = run_stipple({"bench", "--models", "horse", "--paths", "indirect", "--frames", "1",
                                         "--warmup", "0", "--width", "320", "--height", "256", "--models-dir",
                                         models.string(), "--out", out.string(), "--queued", "3"});
    std::printf("%s", r.out.c_str());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("not in " + models.string()), std::string::npos);
    EXPECT_NE(r.out.find("procedural UV sphere"), std::string::npos);
    nlohmann::json j = nlohmann::json::parse(read_bytes(out / "results.json"));
    EXPECT_FALSE(j["scans_found"].get<bool>());
    // The command as a shell reads it back (a word with a space was recorded as two).
    EXPECT_NE(j["command"].get<std::string>().find(" --models-dir '" + models.parent_path().string() + "/stipple'\\''s models' --out"),
              std::string::npos)
        << j["command"];
    EXPECT_EQ(j["queued_frames"], 3);
    EXPECT_EQ(j["validation_messages"], 0);
    EXPECT_NE(read_bytes(out / "results.md").find("with 3 frames queued back to back per submission"), std::string::npos);
    ASSERT_EQ(j["models"].size(), 1u);
    EXPECT_TRUE(j["models"][0]["procedural"].get<bool>());
    // Indirect without lines, with Raskar-Cohen lines, then with each kind of object-space line.
    ASSERT_EQ(j["models"][0]["cells"].size(), 5u);
    const char* columns[] = {"indirect", "indirect + lines", "indirect + contours", "indirect + borders",
                             "indirect + creases"};
    for (size_t i = 0; i < 5; ++i) {
        EXPECT_EQ(j["models"][0]["cells"][i]["column"], columns[i]);
        EXPECT_EQ(j["models"][0]["cells"][i]["paper_fps"].is_null(), i >= 2) << columns[i];  // beyond the paper
    }
    // Compared with the row of the same polygon count (the report's header says the models are spheres).
    EXPECT_DOUBLE_EQ(j["models"][0]["cells"][0]["paper_fps"].get<double>(), 60.39);
    EXPECT_FALSE(j.contains("animated")) << "rows named with --models: no animated row unless asked";
}

// The bench's rows are checked against the machine's memory as every command's models are (it generated the
// horse's 276k stipples under a 5 MB limit that info, tone and render refused), and a refusal advises what
// the bench can take (it said "lower --dmax", an option it does not have).
TEST(BenchCommand, ARowBeyondTheMachinesMemoryIsRefusedInOneLine) {
    test::ScopedEnv limit("STIPPLE_HOST_MEMORY_LIMIT", "5M");
    const test::CommandResult r = run_stipple({"bench", "--models", "horse", "--paths", "splat", "--frames", "1", "--warmup",
                                               "0", "--width", "160", "--height", "128", "--models-dir",
                                               test::temp_dir("bench_memory_no_scans").string(), "--out",
                                               test::temp_dir("bench_memory").string()});
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("stipples planned"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the bench draws every row at the default D_max"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("--dmax"), std::string::npos) << r.err;
}

// Where some rows' scans are missing, the report says which rows are spheres, not that all are.
TEST(BenchReport, SaysWhichRowsAreSpheres) {
    bench::BenchResults results;
    results.models_dir = "/scans";
    results.cache_dir = "/cache";
    results.rows_run = 2;
    results.sphere_rows = {"dragon"};
    const std::string some = bench::models_note(results);
    EXPECT_NE(some.find("derived from the scans in /scans"), std::string::npos) << some;
    EXPECT_NE(some.find("but dragon: a PROCEDURAL UV sphere"), std::string::npos) << some;
    results.sphere_rows = {"horse", "dragon"};
    EXPECT_EQ(bench::models_note(results).find("PROCEDURAL UV spheres with each row's polygon count (the scans are not in /scans)"), 0u);
}

TEST(BenchCommand, CompareListsTheCellsThatGotSlower) {
    // An earlier run where the sphere standing in for the horse drew at a million fps on the indirect
    // path and generated a billion stipples a second; it also had a cell this run has not.
    fs::path out = test::temp_dir("bench_compare");
    const std::string old_path = (out / "old.json").string();
    std::ofstream(old_path) << R"({"models": [{"name": "horse", "preprocessing_seconds": 1e-9, "candidate_stipples": 1,
        "cells": [{"column": "indirect", "median_fps": 1e6}, {"column": "cpu", "median_fps": 1.0}]}]})";
    test::CommandResult r = run_stipple({"bench", "--models", "horse", "--paths", "indirect", "--frames", "1", "--warmup",
                                         "0", "--width", "320", "--height", "256", "--models-dir",
                                         test::temp_dir("bench_compare_no_scans").string(), "--out", out.string(),
                                         "--compare", old_path});
    std::printf("%s", r.out.c_str());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("slower: horse / indirect -"), std::string::npos);
    EXPECT_NE(r.out.find("slower: horse / generation -"), std::string::npos);
    EXPECT_NE(r.out.find("missing in this run: horse / cpu"), std::string::npos);
    EXPECT_NE(r.out.find("missing in " + old_path + ": horse / indirect + lines"), std::string::npos);
    EXPECT_NE(r.out.find("compared with " + old_path + ": 2 cells compared, 2 slower by more than 10%, the worst: "),
              std::string::npos);
}

TEST(BenchCommand, BadArgumentsFailWithOneLine) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"bench", "--models", "teapot"}, {"bench", "--paths", "vertex,raytrace"},
          {"bench", "--frames", "0"}, {"bench", "--queued", "0"}, {"bench", "--width", "0"}, {"bench", "--paths", "vertex,,cpu"},
          {"bench", "model.obj"}, {"bench", "--no-such-option"}, {"bench", "--compare", "/nonexistent/old/results.json"},
          // Refused before any model is made (until 2026-12-04 these failed only at the end of the run, or ran
          // twice and wrote a results.json that --compare refused).
          {"bench", "--models", "horse,horse"}, {"bench", "--paths", "vertex,cpu,vertex"}, {"bench", "--cache-dir", ""},
          {"bench", "--out", test::write_file(test::temp_dir("bench_out_file") / "a_file", "x")},
          // A file where the scans' folder should be (until 2026-12-04 it drew spheres as if none were there).
          {"bench", "--models-dir", test::write_file(test::temp_dir("bench_models_file") / "models.obj", "x")},
          // A folder named that is not there (a typo ran the whole bench on spheres until 2026-12-07), and the
          // animated row alone with rows or paths it would not run.
          {"bench", "--models-dir", "/nonexistent/stipple/models"}, {"bench", "--animated-only", "--models", "horse"},
          {"bench", "--animated-only", "--paths", "splat"}}) {
        test::CommandResult r = run_stipple(args);
        EXPECT_EQ(r.exit_code, 1) << args.back();
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(r.err.rfind("stipple: ", 0), 0u) << r.err;
    }
    // A row named as its files are ("low-res-dragon.ply"), without the quotes its space needs, is that row.
    const test::CommandResult twice = run_stipple({"bench", "--models", "low-res-dragon,low-res dragon"});
    EXPECT_EQ(twice.exit_code, 1);
    EXPECT_EQ(twice.err, "stipple: --models: 'low-res dragon' is named twice\n");
}

}  // namespace
}  // namespace stipple
