// libFuzzer target: OBJ meshes (obj_validation, then tinyobjloader and the mesh build).
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "fuzz_input.h"
#include "obj_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        vkrt::loadObjMesh(vkrt::fuzz::writeInput(data, size, ".obj"));
    } catch (const std::runtime_error&) {
    }
    return 0;
}
