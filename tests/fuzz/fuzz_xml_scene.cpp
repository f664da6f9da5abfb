// libFuzzer target: the XML scene loader on arbitrary text (tests/fuzz/README.md).
#include <cstddef>
#include <cstdint>
#include <string>

#include "diagnostics.h"
#include "fuzz_input.h"
#include "scene_loader.h"
#include "xml_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (bool strict : {false, true}) {
        vkrt::Diagnostics diagnostics(strict);
        try {
            vkrt::loadXmlScene(std::string(vkrt::fuzz::kSceneDirectory) + "scene.xml", text, vkrt::LoadOptions{strict}, diagnostics);
        } catch (const vkrt::SceneError&) {
        }
    }
    return 0;
}
