// Fuzz target: a parallel VTK file (.pvti, .pvtr or .pvts, by its type attribute) beside two piece
// files of its own: the piece list, the Source names, extents and frames checked against the
// pieces', the assembly of the whole extent.
#include "fuzz_series_file.h"

namespace {

// Two ImageData pieces of a 3 x 3 x 3 image, split along z at the shared plane z = 1.
constexpr const char* kPieceBottom = R"(<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">
<ImageData WholeExtent="0 2 0 2 0 1" Origin="0 0 0" Spacing="1 1 1"><Piece Extent="0 2 0 2 0 1">
<PointData Scalars="v"><DataArray type="Float32" Name="v" format="ascii">
0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17</DataArray></PointData></Piece></ImageData></VTKFile>
)";
constexpr const char* kPieceTop = R"(<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">
<ImageData WholeExtent="0 2 0 2 1 2" Origin="0 0 0" Spacing="1 1 1"><Piece Extent="0 2 0 2 1 2">
<PointData Scalars="v"><DataArray type="Float32" Name="v" format="ascii">
9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26</DataArray></PointData></Piece></ImageData></VTKFile>
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    tstyles_fuzz::writeScratchFile("piece_0.vti", kPieceBottom);
    tstyles_fuzz::writeScratchFile("piece_1.vti", kPieceTop);
    tstyles_fuzz::openSeriesFile("input.pvti", tstyles_fuzz::asText(data, size));
    return 0;
}
