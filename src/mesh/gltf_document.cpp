#include "mesh/gltf_document.hpp"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/gltf_draco.hpp"
#include "mesh/gltf_meshopt.hpp"
#include "mesh/glb_container.hpp"
#include "mesh/gltf_validate.hpp"
#include "mesh/loader_util.hpp"

namespace stipple {

namespace {

// Images play no part in stippling: skip decoding them (and any failure to).
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

// Bytes from memory have no folder: a reference to an external file is refused, not looked up in
// the current directory.
bool no_external_file(std::vector<unsigned char>*, std::string* err, const std::string& uri, void*) {
    if (err) *err = "external file '" + uri + "' cannot be read: the model was not loaded from a file";
    return false;
}
bool no_file_exists(const std::string&, void*) { return false; }
std::string unexpanded(const std::string& path, void*) { return path; }
bool no_file_written(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

}  // namespace

tinygltf::Model read_gltf_model(const std::string& path, std::string_view bytes, const std::filesystem::path* base_dir,
                                std::string* decoded) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool binary = ext == ".glb";
    if (bytes.size() > UINT32_MAX) fail_file(path, "a glTF file of 4 GiB or more is not supported");
    nlohmann::json doc = validate_gltf(path, bytes, binary, base_dir);

    // Placeholder buffers of EXT_meshopt_compression, and Draco primitives' indices, get data tinygltf can
    // load: the file goes to it rewritten.
    const MeshoptPlan meshopt = prepare_meshopt(doc, binary);
    const bool draco_stand_ins = prepare_draco(doc);
    std::string rewritten;
    if (!meshopt.placeholders.empty() || draco_stand_ins) {
        rewritten = binary ? join_glb(doc.dump(), split_glb(path, bytes).bin) : doc.dump();
        if (rewritten.size() > UINT32_MAX) fail_file(path, "a glTF file of 4 GiB or more is not supported");
        bytes = rewritten;
    }

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skip_image, nullptr);
    if (!base_dir) loader.SetFsCallbacks({&no_file_exists, &unexpanded, &no_external_file, &no_file_written, nullptr});
    const std::string dir = base_dir ? base_dir->string() : std::string();
    tinygltf::Model model;
    std::string err, warn;
    const auto size = static_cast<unsigned int>(bytes.size());
    const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), size, dir)
                           : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, dir);
    if (!ok) fail_file(path, "cannot read glTF: " + one_line(err.empty() ? warn : err));
    if (!warn.empty()) std::fprintf(stderr, "%s: warning: %s\n", path.c_str(), one_line(warn).c_str());
    if (!meshopt.empty()) decode_meshopt(path, meshopt, model);
    const size_t draco_primitives = decode_draco(path, model);
    if (decoded) {
        auto count = [](size_t n, const char* one) { return std::to_string(n) + " " + one + (n == 1 ? "" : "s"); };
        std::vector<std::string> parts;
        if (!meshopt.views.empty()) parts.push_back("EXT_meshopt_compression (" + count(meshopt.views.size(), "buffer view") + ")");
        if (draco_primitives) parts.push_back("KHR_draco_mesh_compression (" + count(draco_primitives, "primitive") + ")");
        const auto used = doc.find("extensionsUsed");
        if (used != doc.end() && used->is_array())
            for (const nlohmann::json& e : *used)
                if (e == "KHR_mesh_quantization") parts.push_back("KHR_mesh_quantization");
        decoded->clear();
        for (const std::string& part : parts) *decoded += (decoded->empty() ? "" : ", ") + part;
    }
    return model;
}

}  // namespace stipple
