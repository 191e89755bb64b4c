// The reader options in one table, as the compositor table holds the compositors: each line is an
// option of `render`, `info`, `view`, `scene`, `animate`, `convert` and `bench`, and a keyword of
// Python's tstyles.open(): how each spells it, what kind of value it takes, its bounds or choices,
// its default and help, and how its text becomes a field of ReadOptions. The command line registers
// its options from here, Python maps its keywords through here, the opener refuses from here what a
// format does not take (the format rows name their format-only options by these spellings), and the
// docs' table of options in readers.md is written from here (doc_tables.h).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "tstyles/data/read_options.h"

namespace tstyles {

enum class ReaderOptionKind {
    Text,        // any text ("" is not given)
    Flag,        // on when given
    WholeNumber, // an integer within [low, high]
    Number,      // a finite number within the bounds
    Choice,      // one of `choices`
    Steps,       // FIRST:END:STRIDE
    ValueRange,  // LO:HI
    Dims,        // NXxNYxNZ
    MemorySize,  // 512M, 2G, bytes
    Files,       // one or more paths, comma-separated or repeated
};

struct ReaderOptionLine {
    std::string_view key;        // "level": the name in ReaderOptionTexts
    std::string_view cli;        // "--level"
    std::string_view python;     // "level": the keyword of tstyles.open()
    ReaderOptionKind kind;
    std::string_view valueName;  // "N", "FIRST:END:STRIDE": in the help and the docs
    // WholeNumber and Number: the bounds; `lowExclusive` makes the low bound open.
    double low = 0.0;
    double high = 0.0;
    bool lowExclusive = false;
    std::vector<std::string_view> choices;  // Choice: the values allowed
    std::string_view defaultText;           // how the default reads, "" where the help says it
    std::string_view help;
    // Taken by a tstyles manifest too (else refused there); which formats take it is said by their
    // rows (format_table.cpp), isFormatOnly().
    bool forManifest = false;
    // Sets the field from the given texts (checked against the line already); `spelling` names the
    // option in a message.
    void (*set)(ReadOptions& options, const std::vector<std::string>& texts, const std::string& spelling) = nullptr;
    // Whether `options` holds a value given for it (not the default).
    bool (*given)(const ReadOptions& options) = nullptr;
};

// Whether only some formats take the option: those whose rows name it (format_table.cpp); the
// others refuse it. An option no row names is every format's.
bool isFormatOnly(const ReaderOptionLine& line);

// Every reader option, in the order of the help.
const std::vector<ReaderOptionLine>& readerOptionLines();
// The line of a command-line spelling ("--level"), a key ("level") or a Python keyword; null if none.
const ReaderOptionLine* readerOptionNamed(std::string_view name);

// The texts a user gave, per key: one for most options, "true" for a flag, several for Files.
using ReaderOptionTexts = std::map<std::string, std::vector<std::string>>;

// The options the texts give, each checked against its line (an InputError names the option as
// the command line spells it, with readable bounds or the choices); an unknown key is an error too.
ReadOptions readOptionsFrom(const ReaderOptionTexts& texts);
// The value `text` gives a WholeNumber, Number or Choice line, or an InputError naming its bounds.
void checkReaderOptionText(const ReaderOptionLine& line, const std::string& text);
// The bounds or choices of a line as a reader reads them: "0 or more", "above 1 and at most 10",
// "refuse, resolution or steps"; "" where the kind has none.
std::string readerOptionBounds(const ReaderOptionLine& line);

// The lines whose value `options` holds.
std::vector<const ReaderOptionLine*> readerOptionsGiven(const ReadOptions& options);

// The docs' table of options (docs/readers.md), one row per line, in Markdown, between these markers.
std::string readerOptionsMarkdown();
inline constexpr const char* kReaderOptionTableBegin =
    "<!-- The table of reader options is generated from src/data/reader_option_table.cpp: "
    "build/tools/write_doc_tables docs -->";
inline constexpr const char* kReaderOptionTableEnd = "<!-- End of the generated table of reader options. -->";

}  // namespace tstyles
