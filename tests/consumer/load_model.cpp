// A user's program against the installed ctess::models: writes a quad as OBJ, loads it back, checks its
// counts and its adjacency (docs/models.md).
#include <ctess/runtime/models.hpp>

#include <cstdio>
#include <fstream>

int main() {
    const char* path = "consumer_quad.obj";
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    const ctess::models::LoadResult r = ctess::models::load_model(path);
    if (!r) {
        std::fprintf(stderr, "%s\n", r.error.message.c_str());
        return 1;
    }
    const ctess::models::Model& m = *r.model;
    const ctess::models::Adjacency a = ctess::models::build_adjacency(m);
    const bool ok = m.vertex_count() == 4 && m.quad_count() == 1 && m.triangle_count() == 0 &&
                    a.tessellation_indices.size() == 24 &&
                    ctess::models::open_edge_count(m, a.position_ids) == 4;
    std::printf("consumer: models %s\n", ok ? "ok" : "wrong");
    return ok ? 0 : 1;
}
