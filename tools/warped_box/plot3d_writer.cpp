// Plot3D records: a 4-byte length before and after each record's payload.
#include "plot3d_writer.h"

#include <bit>
#include <cstdint>
#include <span>

#include "tstyles/core/atomic_file.h"

namespace warped_box {
namespace {

class RecordWriter {
public:
    void begin() {
        start_ = bytes_.size();
        word(0);
    }
    void end() {
        const auto payload = std::uint32_t(bytes_.size() - start_ - 4);
        for (int index = 0; index < 4; ++index) bytes_[start_ + std::size_t(index)] = std::uint8_t(payload >> (8 * index));
        word(payload);
    }
    void word(std::uint32_t value) {
        for (int index = 0; index < 4; ++index) bytes_.push_back(std::uint8_t(value >> (8 * index)));
    }
    void real(float value) { word(std::bit_cast<std::uint32_t>(value)); }
    void dims(glm::ivec3 dims) {
        begin();
        for (int axis = 0; axis < 3; ++axis) word(std::uint32_t(dims[axis]));
        end();
    }
    void save(const std::filesystem::path& file) const {
        tstyles::writeFileAtomically(file, std::as_bytes(std::span(bytes_)));
    }

private:
    std::vector<std::uint8_t> bytes_;
    std::size_t start_ = 0;
};

}  // namespace

void writePlot3DGrid(const tstyles::StructuredGrid& grid, const std::filesystem::path& file) {
    RecordWriter writer;
    writer.dims(grid.dims);
    writer.begin();
    for (int axis = 0; axis < 3; ++axis)
        for (const glm::vec3& node : *grid.nodes) writer.real(node[axis]);
    writer.end();
    writer.save(file);
}

void writePlot3DSolution(glm::ivec3 dims, double time, const std::array<std::vector<float>, 5>& q,
                         const std::filesystem::path& file) {
    RecordWriter writer;
    writer.dims(dims);
    writer.begin();
    for (float value : {0.5f, 0.0f, 1.0e6f, float(time)}) writer.real(value);  // mach, alpha, Reynolds, time
    writer.end();
    writer.begin();
    for (const std::vector<float>& component : q)
        for (float value : component) writer.real(value);
    writer.end();
    writer.save(file);
}

}  // namespace warped_box
