#include <cstdio>

#include "anim/describe.hpp"
#include "cli/args.hpp"
#include "cli/cache_options.hpp"
#include "cli/commands.hpp"
#include "cli/object_options.hpp"
#include "core/error.hpp"
#include "core/printf_string.hpp"
#include "core/utf8.hpp"
#include "stipple/object_data.hpp"

namespace stipple::cli {

namespace {

// A JSON string of `text`; bytes that are not UTF-8 (a Latin-1 file name) become U+FFFD, since JSON text
// is Unicode (they were copied, and the output did not parse).
std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (size_t i = 0; i < text.size();) {
        const size_t length = utf8_sequence_length(text, i);
        if (length == 0) {
            out += "\\ufffd";
            ++i;
            continue;
        }
        if (length > 1) {
            out += text.substr(i, length);
            i += length;
            continue;
        }
        const char c = text[i++];
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) {
            char escaped[8];
            std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
            out += escaped;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

// What loading did to the file's winding (Mesh::winding), in words.
std::string describe_winding(const WindingRepair& w) {
    std::string out;
    auto add = [&](const std::string& clause) { out += (out.empty() ? "" : "; ") + clause; };
    const std::string parts = std::to_string(w.parts) + (w.parts == 1 ? " part" : " parts");
    if (w.triangles_turned > 0) {
        std::string why;
        if (w.wound_against > 0) why = std::to_string(w.wound_against) + " wound against their neighbours";
        if (w.parts_turned_outward > 0)
            why += (why.empty() ? "" : ", ") + std::to_string(w.parts_turned_outward) + " of " + parts + " inside out" +
                   (w.parts_turned_to_normals > 0 ? ", " + std::to_string(w.parts_turned_to_normals) + " of them by the file's normals" : "");
        add(std::to_string(w.triangles_turned) + " triangles turned (" + why + ")");
    }
    if (w.normals_turned > 0) add(std::to_string(w.normals_turned) + " file normals turned to agree with their faces");
    if (w.conflicting_edges > 0)
        add(std::to_string(w.conflicting_edges) + " edges join triangles no winding can make agree");
    return out.empty() ? "as in the file (" + parts + ")" : out;
}

// The animation fields of --json: empty lists for a model of no glTF animation, skin or morph target; a glTF
// model that nothing moves lists what it holds with "rest_pose_only" true (false for every other model).
std::string animation_json(const ObjectData& object) {
    std::string out = "\"animations\": [";
    const bool still = !object.motion && !anim::describe_lines(object.still).empty();
    if (!object.motion && !still) return out + "], \"rest_pose_only\": false";
    const anim::AnimationDescription d = still ? object.still : anim::describe_animation(*object.motion.model);
    for (size_t i = 0; i < d.animations.size(); ++i)
        out += (i ? ", " : "") + std::string("{\"name\": ") + json_string(d.animations[i].name) +
               ", \"duration\": " + std::to_string(d.animations[i].duration) +
               ", \"channels\": " + std::to_string(d.animations[i].channels) +
               ", \"idle_channels\": " + std::to_string(d.animations[i].idle_channels) + "}";
    out += "], \"skins\": [";
    for (size_t i = 0; i < d.skins.size(); ++i)
        out += (i ? ", " : "") + std::string("{\"name\": ") + json_string(d.skins[i].name) +
               ", \"joints\": " + std::to_string(d.skins[i].joints) + "}";
    out += "], \"morph_targets\": [";
    for (size_t i = 0; i < d.morphs.size(); ++i) {
        out += (i ? ", " : "") + std::string("{\"mesh\": ") + json_string(d.morphs[i].mesh_name) + ", \"targets\": [";
        for (size_t k = 0; k < d.morphs[i].target_names.size(); ++k)
            out += (k ? ", " : "") + json_string(d.morphs[i].target_names[k]);
        out += "]}";
    }
    if (still) return out + "], \"rest_pose_only\": true";  // nothing moves it: no stretch to measure
    out += "], \"rest_pose_only\": false";
    const anim::StretchHeadroom& h = *object.motion.headroom;
    char stretch[256];
    std::snprintf(stretch, sizeof stretch,
                  ", \"stretch\": {\"max_area_ratio\": %.6g, \"headroom_cap\": %.6g, \"stretched_polygons\": %zu, "
                  "\"capped_polygons\": %zu, \"opened_polygons\": %zu, \"candidate_factor\": %.6g}",
                  double(h.max_ratio), double(h.cap), h.stretched_triangles, h.capped_triangles, h.opened_triangles,
                  h.candidate_factor);
    return out + stretch;
}

}  // namespace

CommandOptions info_command_options() {
    CommandOptions accepted{object_flags(), object_options()};
    accepted.flags.insert("--json");
    accepted.options.merge(cache_options());
    return accepted;
}

int run_info(const std::vector<std::string>& argv) {
    const CommandOptions accepted = info_command_options();
    Args args(argv, accepted.flags, accepted.options);
    apply_cache_options(args);
    args.expect_at_most_positionals(1, "info needs exactly one MODEL");
    if (args.positionals().size() != 1) fail("info needs exactly one MODEL (see stipple --help)");
    const std::string path = args.positionals()[0];
    ObjectParams params = read_object_params(args);
    const ObjectData object = load_object_data(path, params.generation);
    const Mesh& mesh = *object.mesh;
    const StippleSet& stipples = *object.stipples;
    Bounds bounds = compute_bounds(mesh);
    bounds.min += glm::vec3(mesh.origin), bounds.max += glm::vec3(mesh.origin);  // in the file's coordinates
    double area = total_area(mesh);
    double stipples_per_second =
        stipples.generation_seconds > 0 ? stipples.size() / stipples.generation_seconds : 0.0;
    if (args.flag("--json")) {
        std::printf(
            "{\"model\": %s, \"triangles\": %zu, \"vertices\": %zu, \"stipple_candidates\": %zu, "
            "\"surface_area\": %.9g, \"bounds_min\": [%.9g, %.9g, %.9g], \"bounds_max\": [%.9g, %.9g, %.9g], "
            "\"bounding_sphere\": {\"center\": [%.9g, %.9g, %.9g], \"radius\": %.9g}, "
            "\"stipple_density_per_area\": %.9g, \"poisson_radius\": %.9g, "
            "\"load_seconds\": %.6f, \"generation_seconds\": %.6f, \"stipples_per_second\": %s, "
            "\"from_cache\": %s, \"winding\": {\"parts\": %zu, \"triangles_turned\": %zu, \"wound_against\": %zu, "
            "\"parts_turned_outward\": %zu, \"parts_turned_to_normals\": %zu, \"normals_turned\": %zu, \"conflicting_edges\": %zu, \"border_edges\": %zu}, "
            "\"duplicates_dropped\": %zu, \"decoded\": %s, %s}\n",
            json_string(path).c_str(), mesh.triangle_count(), mesh.vertex_count(), stipples.size(), area, bounds.min.x,
            bounds.min.y, bounds.min.z, bounds.max.x, bounds.max.y, bounds.max.z, object.bounds.center.x,
            object.bounds.center.y, object.bounds.center.z, object.bounds.radius,
            stipples.density_per_area, stipples.poisson_radius, object.load_seconds,
            // Read from the cache, the figure would be the cache's reading speed (83M/s), not generation's.
            stipples.generation_seconds,
            stipples.from_cache || stipples_per_second <= 0.0 ? "null" : printf_string("%.1f", stipples_per_second).c_str(),
            stipples.from_cache ? "true" : "false",
            mesh.winding.parts, mesh.winding.triangles_turned, mesh.winding.wound_against,
            mesh.winding.parts_turned_outward, mesh.winding.parts_turned_to_normals, mesh.winding.normals_turned, mesh.winding.conflicting_edges,
            mesh.winding.border_edges, mesh.duplicates_dropped, json_string(mesh.decoded).c_str(),
            animation_json(object).c_str());
    } else {
        std::printf("model:               %s\n", path.c_str());
        std::printf("triangles:           %zu\n", mesh.triangle_count());
        std::printf("vertices:            %zu\n", mesh.vertex_count());
        std::printf("stipple candidates:  %zu\n", stipples.size());
        if (const double dmax = effective_dmax(mesh, params.generation); dmax < 0.999 * double(params.generation.dmax))
            std::printf("D_max:               %g in effect of the %g asked (the stipple budget, max_stipples %llu, caps it)\n", dmax,
                        double(params.generation.dmax), (unsigned long long)params.generation.max_stipples);
        std::printf("surface area:        %.6g\n", area);
        std::printf("winding:             %s\n", describe_winding(mesh.winding).c_str());
        // Whether the depth pass holds its faces facing away (depth_holds_back_faces): seen through a hole they
        // hide what lies behind them.
        if (mesh.winding.border_edges > 0)
            std::printf("surface:             open (%zu border edges): through its holes the inside hides what lies behind\n",
                        mesh.winding.border_edges);
        else
            std::printf("surface:             closed\n");
        if (mesh.duplicates_dropped > 0)
            std::printf("repeated faces:      %zu dropped (the same corners in the same order as an earlier face, or two "
                        "corners at one place)\n",
                        mesh.duplicates_dropped);
        if (!mesh.decoded.empty()) std::printf("decoded:             %s\n", mesh.decoded.c_str());
        std::printf("bounds:              (%.6g, %.6g, %.6g) .. (%.6g, %.6g, %.6g)\n", bounds.min.x, bounds.min.y,
                    bounds.min.z, bounds.max.x, bounds.max.y, bounds.max.z);
        std::printf("bounding sphere:     centre (%.6g, %.6g, %.6g), radius %.6g%s\n", object.bounds.center.x,
                    object.bounds.center.y, object.bounds.center.z, object.bounds.radius,
                    object.motion ? " (every pose of every animation)" : "");
        if (object.motion) {
            const auto lines = anim::describe_lines(anim::describe_animation(*object.motion.model));
            for (size_t i = 0; i < lines.size(); ++i) std::printf("%-21s%s\n", i ? "" : "motion:", lines[i].c_str());
            std::printf("stretch headroom:    %s\n",
                        anim::describe_headroom(*object.motion.headroom, mesh.triangle_count()).c_str());
        } else if (const auto lines = anim::describe_lines(object.still); !lines.empty()) {
            // Its skins and default morph weights shape the mesh drawn, which may differ from the stored one.
            for (size_t i = 0; i < lines.size(); ++i) std::printf("%-21s%s\n", i ? "" : "motion:", lines[i].c_str());
            std::printf("%-21s%s\n", "", object.still.rest_pose_declined
                                               ? "none moves it: drawn as stored (its rest pose collapses faces or leaves the coordinates drawing allows)"
                                               : "none moves it: drawn in its rest pose (skins and morph weights applied)");
        }
        std::printf("load time:           %.3f s (%.0f triangles/s)\n", object.load_seconds,
                    object.load_seconds > 0 ? mesh.triangle_count() / object.load_seconds : 0.0);
        if (stipples.from_cache)
            std::printf("generation time:     %.3f s (read from the stipple cache; STIPPLE_NO_CACHE=1 regenerates)\n",
                        stipples.generation_seconds);
        else
            std::printf("generation time:     %.3f s (%.0f stipples/s)\n", stipples.generation_seconds,
                        stipples_per_second);
    }
    return 0;
}

}  // namespace stipple::cli
