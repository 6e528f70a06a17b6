// ctess_gen_shaders: writes, for one maximum factor, the CP table blob (with the configured uniform-density
// tables, CTESS_UNIFORM_MAX_FACTOR, in its last sections) and the mesh pipeline's compute shaders that read
// it.
//
//   ctess_gen_shaders --max 64 --shaders <repo>/shaders --out <dir>
//
// Output (docs/shaders.md):
//   ctess_mesh_<max>.tables.bin     the CP table blob (u32 little-endian; gen/shaders/table_blob.hpp), for
//   WGSL ctess_mesh_<max>.uniform.tables.bin  the same plus the uniform-density sections, for GLSL
//   ctess_mesh_<max>.uniform.layout.json  the uniform blob's size and its uniform sections' offsets
//   ctess_mesh_<max>_<pass>.comp    GLSL 4.50, one file per entry point (a GLSL module has one main)
//   ctess_mesh_<max>.wgsl           WGSL, every entry point in one module
//   ctess_mesh_<max>.layout.json    the blob's section offsets and size, the entry points and their workgroup
//                                   sizes, and every generated constant (the hosts' and the viewer's layouts)
// The shader templates (shaders/ctess_mesh.*) hold no layout number: the {{CONSTANTS}} placeholder becomes a
// block of `const` lines, from the table blob's layout and from gen/shaders/shader_layout.hpp
// (docs/shaders.md, "Generated constants"). Exit status: 0, or 2 with a message for bad arguments, 1 when a
// file cannot be read or written.
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <ctess/cp/tables_layout.hpp>
#include <ctess/runtime/cp/table_set.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

#include "shader_layout.hpp"
#include "shader_template.hpp"
#include "table_blob.hpp"

namespace {

struct Pass {
    const char* name;   // file suffix
    const char* entry;  // entry point
    std::uint32_t size; // workgroup size (gen/shaders/shader_layout.hpp)
};
constexpr Pass passes[] = {
    {"patch_setup", "ctess_patch_setup", ctess::gen::setup_workgroup},
    {"prefix_sum", "ctess_prefix_sum", ctess::gen::scan_workgroup},
    {"emit_vertices", "ctess_emit_vertices", ctess::gen::emit_workgroup},
    {"emit_triangles", "ctess_emit_triangles", ctess::gen::emit_workgroup},
    {"emit_quad_vertices", "ctess_emit_quad_vertices", ctess::gen::emit_workgroup},
    {"emit_quad_triangles", "ctess_emit_quad_triangles", ctess::gen::emit_workgroup},
    {"emit_displaced_vertices", "ctess_emit_displaced_vertices", ctess::gen::emit_workgroup},
    {"emit_displaced_quad_vertices", "ctess_emit_displaced_quad_vertices", ctess::gen::emit_workgroup},
    {"emit_vector_displaced_vertices", "ctess_emit_vector_displaced_vertices", ctess::gen::emit_workgroup},
    {"emit_vector_displaced_quad_vertices", "ctess_emit_vector_displaced_quad_vertices",
     ctess::gen::emit_workgroup},
    {"split_roots", "ctess_split_roots", ctess::gen::split_workgroup},
    {"split_count", "ctess_split_count", ctess::gen::split_workgroup},
    {"split_scan", "ctess_split_scan", ctess::gen::scan_workgroup},
    {"split_expand", "ctess_split_expand", ctess::gen::split_workgroup},
    {"split_records", "ctess_split_records", ctess::gen::split_workgroup},
    {"split_points", "ctess_split_points", ctess::gen::emit_workgroup},
    {"weld_edges", "ctess_weld_edges", ctess::gen::emit_workgroup},
    {"weld_edge_scan", "ctess_weld_edge_scan", ctess::gen::scan_workgroup},
    {"weld_count", "ctess_weld_count", ctess::gen::emit_workgroup},
    {"weld_writers", "ctess_weld_writers", ctess::gen::emit_workgroup},
    {"weld_scan", "ctess_weld_scan", ctess::gen::scan_workgroup},
    {"weld_triangles", "ctess_weld_triangles", ctess::gen::emit_workgroup},
    {"weld_lone_vertices", "ctess_weld_lone_vertices", ctess::gen::emit_workgroup},
    {"weld_keys", "ctess_weld_keys", ctess::gen::emit_workgroup},
    {"weld_sort_step", "ctess_weld_sort_step", ctess::gen::emit_workgroup},
    {"weld_sort_local", "ctess_weld_sort_local", ctess::gen::emit_workgroup},
    {"weld_rank_blocks", "ctess_weld_rank_blocks", ctess::gen::emit_workgroup},
    {"weld_rank_scan", "ctess_weld_rank_scan", ctess::gen::scan_workgroup},
    {"weld_rank_write", "ctess_weld_rank_write", ctess::gen::emit_workgroup},
    {"weld_keep", "ctess_weld_keep", ctess::gen::emit_workgroup},
    {"weld_owner_counts", "ctess_weld_owner_counts", ctess::gen::emit_workgroup},
    {"weld_sorted_triangles", "ctess_weld_sorted_triangles", ctess::gen::emit_workgroup}};

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        std::string why = "cannot read ";
        why += path;
        throw std::runtime_error(why);
    }
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_file(const std::string& path, std::string_view data) {
    std::ofstream out(path, std::ios::binary);
    out.write(data.data(), static_cast<std::streamsize>(data.size()));
    if (!out) {
        std::string why = "cannot write ";
        why += path;
        throw std::runtime_error(why);
    }
}

// One generated constant (a u32) and the definition it comes from.
struct Constant {
    std::string name;
    std::uint32_t value = 0;
    std::string source;
};

// Every constant of the generated block, in its order: the blob's layout, then shader_layout.hpp's.
std::vector<Constant> constants(const ctess::gen::TableBlobLayout& l) {
    std::vector<Constant> v;
    auto put = [&v](const char* name, std::uint32_t value, const char* source) {
        v.push_back({name, value, source});
    };
    put("MAX_FACTOR", l.max_factor, "CpTableSet::max_factor");
    put("TOKENS", l.tokens, "CpTableSet::tokens");
    put("SHAPES", l.shapes, "CpTableSet::shapes");
    put("TOKEN_RANGE", l.token_range, "blob section (table_blob.hpp)");
    put("TOKEN_RECORD", l.token_record, "blob section");
    put("POINT", l.point, "blob section");
    put("COLUMN_RECORD", l.column_record, "blob section");
    put("COLUMN_POOL", l.column_pool, "blob section");
    put("GAP_OFFSET", l.gap_offset, "blob section");
    put("GAP_WORD", l.gap_word, "blob section");
    put("T1_LAST_FAN", l.t1_last_fan, "blob section");
    put("SEARCH_WINDOW", ctess::cp::tables::search_window, "cp::tables::search_window");
    put("UNIFORM_MAX_FACTOR", l.uniform_max_factor, "UniformTableSet::max_factor");
    put("UNIFORM_OFFSET", l.uniform_offset, "blob section");
    put("UNIFORM_INTERIOR", l.uniform_interior, "blob section");
    put("UNIFORM_TRIANGLE", l.uniform_triangle, "blob section");
    for (const ctess::gen::ShaderConstant& c : ctess::gen::shader_constants) put(c.name, c.value, c.source);
    return v;
}

enum class Language { glsl, wgsl };

std::string constants_block(const std::vector<Constant>& v, Language lang) {
    std::string out =
        "// ---- generated by gen/shaders/gen_shaders.cpp from the C++ definitions (docs/shaders.md, "
        "\"Generated constants\") ----\n";
    for (const Constant& c : v) {
        const std::string value = std::to_string(c.value) + "u";
        if (lang == Language::wgsl)
            out += "const " + c.name + ": u32 = " + value + ";";
        else
            out += "const uint " + c.name + " = " + value + ";";
        out += " // " + c.source + "\n";
    }
    out += "// ---- end of the generated constants ----";
    return out;
}

std::string json_constants(const std::vector<Constant>& v) {
    std::string out = "{";
    for (std::size_t k = 0; k < v.size(); ++k) {
        out += k ? ",\n    \"" : "\n    \"";
        out += v[k].name + "\": " + std::to_string(v[k].value);
    }
    return out + "\n  }";
}

int usage(const char* why) {
    std::fprintf(stderr,
                 "ctess_gen_shaders: %s\nusage: ctess_gen_shaders --max 64|256 --shaders DIR --out DIR\n",
                 why);
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    std::string max, shaders, out;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (i + 1 >= argc) return usage("missing value after an option");
        if (arg == "--max")
            max = argv[++i];
        else if (arg == "--shaders")
            shaders = argv[++i];
        else if (arg == "--out")
            out = argv[++i];
        else
            return usage("unknown option");
    }
    if (max != "64" && max != "256") return usage("--max must be 64 or 256");
    if (shaders.empty() || out.empty()) return usage("--shaders and --out are required");
    const ctess::rt::CpTableSet& tables = max == "64" ? ctess::rt::cp_tables_64 : ctess::rt::cp_tables_256;
    try {
        const ctess::gen::TableBlob blob = ctess::gen::build_table_blob(tables, ctess::rt::uniform_tables);
        const std::string prefix = out + "/ctess_mesh_" + max;
        // Two blobs: .uniform.tables.bin, every section (both patterns), and .tables.bin, the CP sections and
        // the padding only (enough for the CP pattern; docs/shaders.md).
        write_file(prefix + ".uniform.tables.bin",
                   std::string_view(reinterpret_cast<const char*>(blob.words.data()), blob.words.size() * 4));
        std::vector<std::uint32_t> cp_words(blob.words.begin(),
                                            blob.words.begin() + blob.layout.uniform_offset);
        cp_words.insert(cp_words.end(), ctess::gen::blob_padding, 0u);
        write_file(prefix + ".tables.bin",
                   std::string_view(reinterpret_cast<const char*>(cp_words.data()), cp_words.size() * 4));

        const std::vector<Constant> v = constants(blob.layout);
        const std::string glsl = read_file(shaders + "/ctess_mesh.comp.glsl");
        for (const Pass& p : passes) {
            const std::map<std::string, std::string, std::less<>> values = {
                {"CONSTANTS", constants_block(v, Language::glsl)},
                {"LOCAL_SIZE", std::to_string(p.size)},
                {"ENTRY", p.entry}};
            write_file(prefix + "_" + p.name + ".comp", ctess::gen::fill_template(glsl, values));
        }
        const std::string wgsl = read_file(shaders + "/ctess_mesh.wgsl");
        write_file(prefix + ".wgsl",
                   ctess::gen::fill_template(wgsl, {{"CONSTANTS", constants_block(v, Language::wgsl)}}));

        const ctess::gen::TableBlobLayout& l = blob.layout;
        std::ostringstream json;
        json << "{\n  \"max_tess_factor\": " << l.max_factor << ",\n  \"tables_words\": " << cp_words.size()
             << ",\n  \"tables_bytes\": " << cp_words.size() * 4
             << ",\n  \"sections\": {\"token_range\": " << l.token_range
             << ", \"token_record\": " << l.token_record << ", \"point\": " << l.point
             << ", \"column_record\": " << l.column_record << ", \"column_pool\": " << l.column_pool
             << ", \"gap_offset\": " << l.gap_offset << ", \"gap_word\": " << l.gap_word
             << ", \"t1_last_fan\": " << l.t1_last_fan << "},\n  \"passes\": [";
        for (std::size_t k = 0; k < std::size(passes); ++k)
            json << (k ? ", " : "") << "{\"name\": \"" << passes[k].name << "\", \"entry\": \""
                 << passes[k].entry << "\", \"workgroup_size\": " << passes[k].size << "}";
        json << "],\n  \"patch_words\": " << sizeof(ctess::rt::PatchRecord) / 4
             << ",\n  \"limits\": {\"max_dispatch_workgroups\": " << ctess::rt::max_dispatch_workgroups
             << ", \"max_patches\": " << ctess::rt::max_pipeline_patches
             << ", \"max_vertices\": " << ctess::rt::max_pipeline_vertices
             << ", \"max_triangles\": " << ctess::rt::max_pipeline_triangles
             << "},\n  \"constants\": " << json_constants(v) << "\n}\n";
        write_file(prefix + ".layout.json", json.str());
        // The uniform blob: the same CP sections, then the uniform-density ones (docs/shaders.md).
        std::ostringstream uniform_json;
        uniform_json << "{\n  \"max_tess_factor\": " << l.max_factor
                     << ",\n  \"uniform_max_factor\": " << l.uniform_max_factor
                     << ",\n  \"tables_words\": " << l.words << ",\n  \"tables_bytes\": " << l.words * 4
                     << ",\n  \"sections\": {\"uniform_offset\": " << l.uniform_offset
                     << ", \"uniform_interior\": " << l.uniform_interior
                     << ", \"uniform_triangle\": " << l.uniform_triangle << "}\n}\n";
        write_file(prefix + ".uniform.layout.json", uniform_json.str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ctess_gen_shaders: %s\n", e.what());
        return 1;
    }
    return 0;
}
