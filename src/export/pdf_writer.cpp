#include "export/pdf_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include <cairo-pdf.h>
#include <cairo.h>

#include "core/error.hpp"
#include "io/output_file.hpp"

namespace stipple::plot {

namespace {

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using Context = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

// Where cairo's output goes: the file write_output opened, and the first write error's errno (cairo names no
// cause for a failed write).
struct Stream {
    std::FILE* out = nullptr;
    int error = 0;
};

cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
    Stream& stream = *static_cast<Stream*>(closure);
    errno = 0;
    if (std::fwrite(data, 1, length, stream.out) == length) return CAIRO_STATUS_SUCCESS;
    if (!stream.error) stream.error = errno ? errno : EIO;
    return CAIRO_STATUS_WRITE_ERROR;
}

void check(cairo_status_t status, const std::string& path, const Stream& stream) {
    if (status == CAIRO_STATUS_SUCCESS) return;
    fail_file(path, std::string("cannot write PDF: ") +
                        (status == CAIRO_STATUS_WRITE_ERROR && stream.error ? std::strerror(stream.error) : cairo_status_to_string(status)));
}

void set_colour(cairo_t* cr, glm::vec3 colour) { cairo_set_source_rgb(cr, colour.r, colour.g, colour.b); }

void set_pen(cairo_t* cr, double width_mm) {
    cairo_set_line_width(cr, width_mm);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
}

// All dots of a layer are one path, filled or stroked once: one operator per layer keeps the file
// and cairo's work small.
void draw_dots(cairo_t* cr, const PlotLayer& layer, DotStyle style) {
    cairo_new_path(cr);
    for (const PlotDot& dot : layer.dots) {
        if (style == DotStyle::Tick) {
            const std::array<glm::dvec2, 2> ends = dot_stroke_ends(dot, style, layer.stroke_mm);
            cairo_move_to(cr, ends[0].x, ends[0].y);
            cairo_line_to(cr, ends[1].x, ends[1].y);
            continue;
        }
        const double r = style == DotStyle::Filled ? dot.radius_mm : circle_stroke_radius(dot.radius_mm, layer.stroke_mm);
        cairo_new_sub_path(cr);
        cairo_arc(cr, dot.mm.x, dot.mm.y, std::max(r, 0.001), 0.0, 2.0 * std::numbers::pi);
        cairo_close_path(cr);
    }
    if (style == DotStyle::Filled) {
        cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);  // overlapping dots stay solid
        cairo_fill(cr);
    } else {
        set_pen(cr, layer.stroke_mm);
        cairo_stroke(cr);
    }
}

void draw_lines(cairo_t* cr, const PlotLayer& layer) {
    cairo_new_path(cr);
    for (const Polyline& line : layer.lines) {
        if (line.points.empty()) continue;
        cairo_move_to(cr, line.points[0].x, line.points[0].y);
        for (size_t i = 1; i < line.points.size(); ++i) cairo_line_to(cr, line.points[i].x, line.points[i].y);
        if (line.points.size() == 1) cairo_rel_line_to(cr, 0.0, 0.0);
        if (line.closed) cairo_close_path(cr);
    }
    set_pen(cr, layer.stroke_mm);
    cairo_stroke(cr);
}

// SOURCE_DATE_EPOCH as cairo's ISO 8601 date ("2026-12-05T10:00:00Z"), or nothing where it is unset or
// not a whole number of seconds (said once a process on stderr: a typo would otherwise leave the PDF dated
// today without a word, and its bytes different from run to run).
std::optional<std::string> source_date() {
    const char* text = std::getenv("SOURCE_DATE_EPOCH");
    if (!text || !*text) return std::nullopt;
    const auto malformed = [&]() -> std::optional<std::string> {
        static bool said = false;
        if (!std::exchange(said, true))
            std::fprintf(stderr, "stipple: warning: SOURCE_DATE_EPOCH=%s is not a whole number of seconds since 1970: the PDF "
                                 "is dated now\n", text);
        return std::nullopt;
    };
    char* end = nullptr;
    errno = 0;
    const long long seconds = std::strtoll(text, &end, 10);
    if (errno != 0 || *end != '\0' || seconds < 0) return malformed();
    const std::time_t t = static_cast<std::time_t>(seconds);
    std::tm utc{};
    if (!gmtime_r(&t, &utc) || utc.tm_year + 1900 > 9999) return malformed();
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return std::string(date);
}

// The PDF written to `out`, named `path` in messages.
void write_pdf_to(const PlotPlan& plan, std::FILE* out, const std::string& path) {
    const double width_pt = plan.layout.page.width_mm * kPointsPerMm, height_pt = plan.layout.page.height_mm * kPointsPerMm;
    Stream stream{out};
    Surface surface(cairo_pdf_surface_create_for_stream(write_to_stream, &stream, width_pt, height_pt), &cairo_surface_destroy);
    check(cairo_surface_status(surface.get()), path, stream);
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE, "stipple drawing");
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "stipple");
    // Reproducible builds' convention: SOURCE_DATE_EPOCH (seconds since 1970) is the creation date, so that
    // the same command writes the same bytes; cairo writes the time of day otherwise.
    if (const std::optional<std::string> date = source_date()) {
        cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, date->c_str());
        cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_MOD_DATE, date->c_str());
    }
    Context context(cairo_create(surface.get()), &cairo_destroy);
    cairo_t* cr = context.get();
    cairo_scale(cr, kPointsPerMm, kPointsPerMm);  // user units are millimetres from here on

    if (plan.fill_paper) {
        set_colour(cr, plan.paper);
        cairo_paint(cr);
    }
    for (const PlotLayer& layer : plan.layers) {
        cairo_push_group(cr);
        set_colour(cr, layer.ink);
        if (layer.kind == LayerKind::Stipples) draw_dots(cr, layer, plan.dot_style);
        else draw_lines(cr, layer);
        cairo_pop_group_to_source(cr);
        cairo_paint(cr);
    }
    check(cairo_status(cr), path, stream);
    cairo_surface_finish(surface.get());
    check(cairo_surface_status(surface.get()), path, stream);
}

}  // namespace

void write_pdf(const PlotPlan& plan, const std::string& path) {
    write_output(path, "cannot write PDF", [&](std::FILE* out) { write_pdf_to(plan, out, path); });
}

}  // namespace stipple::plot
