// libFuzzer: ctess::models::load_model_from_memory on arbitrary bytes as binary glTF (.glb). Any input gives
// a model or an error (never a crash, a hang or a sanitizer report), and a model always holds the loader's
// promises (docs/models.md): indices in range, finite values, adjacency computable.
#include "fuzz_models.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    ctess::fuzz::check_model_load(data, size, ctess::models::ModelKind::gltf_binary);
    return 0;
}
