// Writes the tables of docs/ that are made from the code's tables, each between its markers,
// through a temporary file and a rename: write_doc_tables docs. The scene keys
// (src/scene/scene_keys.cpp) go into scene-format.md, the compositors (temporal_compositors.h) into
// compositors.md; SceneKeys.TheDocumentedTableIsTheKeyTable and
// CompositorTable.TheDocumentedTableIsTheCompositorTable fail while one differs.
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/scene_keys.h"
#include "tstyles/scene/temporal_compositors.h"

namespace {

struct DocTable {
    const char* document;  // in docs/
    const char* begin;
    const char* end;
    std::string (*table)();
};

constexpr DocTable kDocTables[] = {
    {"scene-format.md", tstyles::kSceneKeyTableBegin, tstyles::kSceneKeyTableEnd, tstyles::sceneKeyTable},
    {"compositors.md", tstyles::kCompositorTableBegin, tstyles::kCompositorTableEnd, tstyles::compositorDocTable},
};

void writeTable(const std::filesystem::path& docs, const DocTable& table) {
    const std::filesystem::path doc = docs / table.document;
    std::ifstream in(doc, std::ios::binary);
    if (!in) tstyles::throwInputError(doc, "", "cannot open it");
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::size_t begin = text.find(table.begin);
    const std::size_t end = text.find(table.end);
    if (begin == std::string::npos || end == std::string::npos || end < begin)
        tstyles::throwInputError(doc, "", "has no markers of its generated table");
    const std::size_t tableStart = begin + std::string(table.begin).size();
    text.replace(tableStart, end - tableStart, "\n" + table.table());
    tstyles::writeFileAtomically(doc, text);
    std::cout << "wrote the generated table into " << doc.string() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: write_doc_tables docs\n";
        return 2;
    }
    try {
        for (const DocTable& table : kDocTables) writeTable(argv[1], table);
        return 0;
    } catch (const tstyles::InputError& error) {
        std::cerr << "write_doc_tables: " << error.what() << "\n";
        return 2;
    }
}
