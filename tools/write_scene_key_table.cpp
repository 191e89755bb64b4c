// Writes the table of scene keys (src/scene/scene_keys.cpp) into docs/scene-format.md, between its
// markers, through a temporary file and a rename: write_scene_key_table docs/scene-format.md.
// The model test SceneKeys.TheDocumentedTableIsTheKeyTable fails while the two differ.
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/scene_keys.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: write_scene_key_table docs/scene-format.md\n";
        return 2;
    }
    const std::filesystem::path doc = argv[1];
    try {
        std::ifstream in(doc, std::ios::binary);
        if (!in) tstyles::throwInputError(doc, "", "cannot open it");
        std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const std::size_t begin = text.find(tstyles::kSceneKeyTableBegin);
        const std::size_t end = text.find(tstyles::kSceneKeyTableEnd);
        if (begin == std::string::npos || end == std::string::npos || end < begin)
            tstyles::throwInputError(doc, "", "has no scene key table markers");
        const std::size_t tableStart = begin + std::string(tstyles::kSceneKeyTableBegin).size();
        text.replace(tableStart, end - tableStart, "\n" + tstyles::sceneKeyTable());
        tstyles::writeFileAtomically(doc, text);
        std::cout << "wrote the scene key table into " << doc.string() << "\n";
        return 0;
    } catch (const tstyles::InputError& error) {
        std::cerr << "write_scene_key_table: " << error.what() << "\n";
        return 2;
    }
}
