// One TIFF file through libtiff: its pages' descriptions and one channel of one page as floats.
// libtiff's own messages never reach stderr; they become InputErrors naming the file and the page.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tstyles/data/series.h"

namespace tstyles {

// What a page holds, as its tags say, once checked to be a grey or multi-channel image of a
// sample type we read.
struct TiffPage {
    std::uint64_t ifdOffset = 0;  // where its directory is, to come back to it directly
    // Its SubIFDs: the same plane at coarser resolutions (an OME-TIFF pyramid), finest first.
    std::vector<std::uint64_t> subIfds;
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::uint16_t samplesPerPixel = 1;
    std::uint16_t bitsPerSample = 8;
    std::uint16_t sampleFormat = 1;  // 1 unsigned, 2 signed, 3 IEEE float
    bool planarSeparate = false;     // PlanarConfiguration 2: each sample in its own strips or tiles
    bool tiled = false;
    std::uint16_t compression = 1;
    // Pixels per resolution unit (0: not given); unit 1 none, 2 inch, 3 centimetre.
    double xResolution = 0.0;
    double yResolution = 0.0;
    std::uint16_t resolutionUnit = 2;

    ValueType valueType() const;  // uint32 is described as float64, which holds it exactly
    // "uint16", "float32", ...: the sample type as the file has it, for notes.
    std::string sampleTypeName() const;
    // Same size, channels and sample type: pages that can be slices of one volume.
    bool sameLayout(const TiffPage& other) const;
};

class TiffFile {
public:
    // Opens and checks the header; `memoryCap` bounds any one allocation libtiff or we make.
    TiffFile(const std::filesystem::path& file, std::uint64_t memoryCap);
    ~TiffFile();
    TiffFile(const TiffFile&) = delete;
    TiffFile& operator=(const TiffFile&) = delete;

    const std::filesystem::path& path() const { return file_; }
    // Every page (IFD) in file order, each checked (sample type, compression, photometric).
    std::vector<TiffPage> readPages();
    // `page`'s reduced-resolution copy at pyramid `level` (1: its first SubIFD), checked like a page.
    TiffPage readSubPage(const TiffPage& page, std::size_t level, std::size_t index);
    // The first page's ImageDescription (ImageJ or OME metadata live there); empty when none.
    std::string firstDescription();
    bool byteSwapped() const;

    // Sample `channel` of page `index` (its IFD at `page.ifdOffset`), rows top-down, x fastest,
    // written to `out` (width * height floats).
    void readPlane(const TiffPage& page, std::size_t index, int channel, float* out);
    // Where the first page's pixel data starts when it is one uncompressed run (ImageJ's files
    // over 4 GiB continue there without IFDs); nothing otherwise.
    std::uint64_t contiguousDataOffset(const TiffPage& first);
    // Plane `plane` of such a run: `first`'s layout, `dataOffset` from contiguousDataOffset.
    void readContiguousPlane(const TiffPage& first, std::uint64_t dataOffset, std::size_t plane, int channel, float* out);

private:
    struct Diagnostics;
    [[noreturn]] void fail(const std::string& field, const std::string& problem);
    void goToPage(const TiffPage& page, std::size_t index);
    void readStrips(const TiffPage& page, std::size_t index, int channel, float* out);
    void readTiles(const TiffPage& page, std::size_t index, int channel, float* out);
    std::vector<std::uint8_t> takeBuffer(std::int64_t bytes, std::size_t index, const char* what);

    std::filesystem::path file_;
    std::uint64_t memoryCap_;
    std::unique_ptr<Diagnostics> diagnostics_;  // libtiff writes its messages here (client data)
    void* tiff_ = nullptr;                     // TIFF*, kept out of this header
};


}  // namespace tstyles
