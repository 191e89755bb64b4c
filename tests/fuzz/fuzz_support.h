// What every fuzz target shares: a scratch folder of its own for inputs that a parser reads by path,
// the small memory cap the parsers get, and the one rule of the harness: an InputError is the
// parser's normal answer to bad input; anything else escaping it is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace tstyles_fuzz {

// 16 MiB: small enough that a size from the input that slips past the checks reaches libFuzzer's
// -malloc_limit_mb (tools/fuzz.sh), large enough for every seed.
inline constexpr std::uint64_t kMemoryCap = std::uint64_t(16) << 20;

// A folder of this process's own under the system's temporary folder, made on first use and
// removed when the process exits (two fuzzers running at once never share files).
const std::filesystem::path& scratchFolder();

// Writes `bytes` to scratchFolder()/name (replacing what was there) and returns its path.
std::filesystem::path writeScratchFile(const std::string& name, std::string_view bytes);

// The fuzzer's bytes as text.
inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// Runs `parse`; an InputError is swallowed (a refusal is a correct answer), any other exception is
// printed and aborts, which libFuzzer reports as a crash with the input that caused it.
template <typename Parse>
void expectInputErrorAtMost(Parse&& parse);

[[noreturn]] void reportEscapedException(const char* what);

}  // namespace tstyles_fuzz

#include "tstyles/core/errors.h"

template <typename Parse>
void tstyles_fuzz::expectInputErrorAtMost(Parse&& parse) {
    try {
        parse();
    } catch (const tstyles::InputError&) {
    } catch (const std::exception& error) {
        reportEscapedException(error.what());
    } catch (...) {
        reportEscapedException("an exception that is not a std::exception");
    }
}
