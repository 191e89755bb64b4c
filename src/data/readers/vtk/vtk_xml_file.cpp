// Loading a VTK XML file: the text up to <AppendedData> is XML; what follows its '_' is the data the
// arrays' offsets point into. The <VTKFile> attributes that say how binary data is laid out are
// read here, once per file.
#include "vtk_xml_file.h"


#include <algorithm>
#include <fstream>

#include "../file_magic.h"
#include "tstyles/core/errors.h"
#include "tstyles/core/input_limits.h"

namespace tstyles {
namespace {

constexpr const char* kAppendedTag = "<AppendedData";

// Reads the file, or with headerOnly only as far as the end of the <AppendedData ...> tag: the
// XML before it is small however large the data after it.
std::string readText(const std::filesystem::path& path, bool headerOnly, std::uint64_t memoryCap) {
    const std::uint64_t size = regularFileSize(path, "VTK XML file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throwInputError(path, "", "cannot be opened for reading");
    std::string text;
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    while (text.size() < size) {
        const std::size_t chunk = std::size_t(std::min<std::uint64_t>(kChunk, size - text.size()));
        // The document parsed from the text is a second copy of it.
        requireMemory(path, "", 2.0 * double(text.size() + chunk), memoryCap, "the XML text of a VTK file");
        const std::size_t start = text.size();
        text.resize(start + chunk);
        in.read(text.data() + start, std::streamsize(chunk));
        if (!in) throwInputError(path, "", "cannot be read");
        if (!headerOnly) continue;
        const std::size_t tag = text.find(kAppendedTag, start >= 16 ? start - 16 : 0);
        if (tag != std::string::npos && text.find('>', tag) != std::string::npos) break;
    }
    return text;
}

VtkBinaryLayout readLayout(const VtkXmlFile& file) {
    VtkBinaryLayout layout;
    const std::string order = file.root.attribute("byte_order").as_string("LittleEndian");
    if (order != "LittleEndian" && order != "BigEndian")
        throwInputError(file.path, "byte_order", "'" + order + "' is neither LittleEndian nor BigEndian");
    layout.bigEndian = order == "BigEndian";
    const std::string header = file.root.attribute("header_type").as_string("UInt32");
    if (header != "UInt32" && header != "UInt64")
        throwInputError(file.path, "header_type", "'" + header + "' is neither UInt32 nor UInt64");
    layout.headerBytes = header == "UInt64" ? 8 : 4;
    const std::string compressor = file.root.attribute("compressor").as_string();
    if (compressor.empty()) layout.compressor = VtkCompressor::None;
    else if (compressor == "vtkZLibDataCompressor") layout.compressor = VtkCompressor::ZLib;
    else if (compressor == "vtkLZ4DataCompressor") layout.compressor = VtkCompressor::LZ4;
    else if (compressor == "vtkLZMADataCompressor") layout.compressor = VtkCompressor::LZMA;
    else
        throwInputError(file.path, "compressor",
                        "unknown compressor '" + compressor +
                            "' (known: vtkZLibDataCompressor, vtkLZ4DataCompressor, vtkLZMADataCompressor)");
    return layout;
}

void findDataset(VtkXmlFile& file) {
    file.root = file.document.child("VTKFile");
    if (!file.root) throwInputError(file.path, "", "is not a VTK XML file: it has no <VTKFile> element");
    const std::string type = file.root.attribute("type").as_string();
    if (type == "Collection")
        throwInputError(file.path, "type", "is a collection: name it with the .pvd extension");
    const bool parallel = type.size() > 1 && type[0] == 'P';
    const std::string serial = parallel ? type.substr(1) : type;
    if (serial != "ImageData" && serial != "RectilinearGrid" && serial != "StructuredGrid")
        throwInputError(file.path, "type",
                        "VTK XML '" + type +
                            "' data is not read (only ImageData, .vti; RectilinearGrid, .vtr; StructuredGrid, .vts; "
                            "and their parallel forms .pvti, .pvtr, .pvts)");
    file.dataset = file.root.child(type.c_str());
    file.parallel = parallel;
    if (!file.dataset) throwInputError(file.path, type, "the <" + type + "> element is missing");
}

// Sets the appended data apart; returns where the XML ends (the text's end when there is none).
std::size_t splitAppendedData(VtkXmlFile& file, bool headerOnly) {
    const std::size_t tag = file.text.find(kAppendedTag);
    if (tag == std::string::npos) return file.text.size();
    file.hasAppendedData = true;
    const std::size_t tagEnd = file.text.find('>', tag);
    if (tagEnd == std::string::npos) throwInputError(file.path, "AppendedData", "the tag is not closed");
    std::size_t marker = tagEnd + 1;
    while (marker < file.text.size() && std::isspace(static_cast<unsigned char>(file.text[marker]))) ++marker;
    if (!headerOnly) {
        if (marker >= file.text.size() || file.text[marker] != '_')
            throwInputError(file.path, "AppendedData", "the data does not start with the '_' marker");
        file.appended = std::string_view(file.text).substr(marker + 1);
    }
    return tagEnd + 1;
}

}  // namespace

std::unique_ptr<VtkXmlFile> loadVtkXmlFile(const std::filesystem::path& path, bool headerOnly,
                                           std::uint64_t memoryCap) {
    auto file = std::make_unique<VtkXmlFile>();
    file->path = path;
    file->headerOnly = headerOnly;
    file->text = readText(path, headerOnly, memoryCap);
    const std::size_t xmlEnd = splitAppendedData(*file, headerOnly);
    std::string xml = file->text.substr(0, xmlEnd);
    if (file->hasAppendedData) xml += "</AppendedData></VTKFile>";
    const pugi::xml_parse_result parsed = file->document.load_buffer(xml.data(), xml.size());
    if (!parsed)
        throwInputError(path, "", std::string("bad XML at byte ") + std::to_string(parsed.offset) + ": " +
                                      parsed.description());
    findDataset(*file);
    file->layout = readLayout(*file);
    if (file->hasAppendedData) {
        const std::string encoding = file->root.child("AppendedData").attribute("encoding").as_string("raw");
        if (encoding != "raw" && encoding != "base64")
            throwInputError(path, "AppendedData", "encoding '" + encoding + "' is neither raw nor base64");
        file->appendedEncoding = encoding == "raw" ? VtkByteStream::Encoding::Raw : VtkByteStream::Encoding::Base64;
    }
    return file;
}

std::size_t lineOf(const VtkXmlFile& file, const pugi::xml_node& node) {
    const std::ptrdiff_t offset = node.offset_debug();
    if (offset < 0 || std::size_t(offset) > file.text.size()) return 0;
    return 1 + std::size_t(std::count(file.text.begin(), file.text.begin() + offset, '\n'));
}

bool looksLikeVtkXml(const std::filesystem::path& path) {
    // The root element, after the XML declaration and any comment.
    return fileStart(path, 512).find("<VTKFile") != std::string::npos;
}

}  // namespace tstyles
