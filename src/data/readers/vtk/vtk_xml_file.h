// A VTK XML file (.vti, .vtr, .vts, or the parallel .pvti, .pvtr, .pvts) as text: the XML parsed with pugixml, and the appended data block,
// which is raw bytes no XML parser can read, set apart before parsing.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include <pugixml.hpp>

#include "vtk_array_bytes.h"

namespace tstyles {

struct VtkXmlFile {
    std::filesystem::path path;
    std::string text;  // the file's bytes (only the XML before the appended data when headerOnly)
    pugi::xml_document document;
    pugi::xml_node root;     // <VTKFile>
    pugi::xml_node dataset;  // <ImageData>, <RectilinearGrid>, <StructuredGrid> or a parallel <P...>
    bool parallel = false;   // a .pvti, .pvtr or .pvts: its pieces are in files of their own
    bool headerOnly = false;
    VtkBinaryLayout layout;
    // The appended data after its '_' marker (empty when the file has none, or headerOnly).
    std::string_view appended;
    VtkByteStream::Encoding appendedEncoding = VtkByteStream::Encoding::Raw;
    bool hasAppendedData = false;
};

// Reads and parses `path`; with headerOnly the appended data is not read (opening a series reads
// each file's description, a time-step's values are read later). `memoryCap` bounds the bytes read.
// Bad XML, a VTKFile of another type, an unknown byte order, header type or compressor are
// InputErrors naming the file and the attribute.
std::unique_ptr<VtkXmlFile> loadVtkXmlFile(const std::filesystem::path& path, bool headerOnly,
                                           std::uint64_t memoryCap);

// The 1-based line of a node in the file, for messages.
std::size_t lineOf(const VtkXmlFile& file, const pugi::xml_node& node);

// Whether the file starts like a VTK XML file (the format table's content sniff).
bool looksLikeVtkXml(const std::filesystem::path& path);

}  // namespace tstyles
