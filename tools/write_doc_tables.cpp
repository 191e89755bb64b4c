// Writes the tables of docs/ that are made from the code's tables (tstyles/scene/doc_tables.h),
// each between its markers, through a temporary file and a rename: write_doc_tables docs.
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "tstyles/core/atomic_file.h"
#include "tstyles/core/errors.h"
#include "tstyles/scene/doc_tables.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: write_doc_tables docs\n";
        return 2;
    }
    try {
        for (const tstyles::GeneratedDocTable& table : tstyles::generatedDocTables()) {
            const std::filesystem::path doc = std::filesystem::path(argv[1]) / table.document;
            std::ifstream in(doc, std::ios::binary);
            if (!in) tstyles::throwInputError(doc, "", "cannot open it");
            const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
            tstyles::writeFileAtomically(doc, tstyles::withGeneratedTable(text, table, doc));
            std::cout << "wrote the generated table into " << doc.string() << "\n";
        }
        return 0;
    } catch (const tstyles::InputError& error) {
        std::cerr << "write_doc_tables: " << error.what() << "\n";
        return 2;
    }
}
