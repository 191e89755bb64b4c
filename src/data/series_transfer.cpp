// The transfer form of a Series: a magic number, the series' own fields, then per time-step its
// fields, grid, values and mask. Numbers in the machine's order (writer and reader are one
// program); values are copied as raw bytes, so NaN payloads and signed zeros survive.
#include "series_transfer.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

#include <fcntl.h>
#include <unistd.h>

namespace tstyles {
namespace {

constexpr std::uint64_t kMagic = 0x3153534554535453ULL;  // "TSTSESS1"

[[noreturn]] void failSystem(const char* doing) {
    throw std::runtime_error(std::string("series transfer: cannot ") + doing + ": " + std::strerror(errno));
}

class TransferWriter {
public:
    explicit TransferWriter(int fd) : fd_(fd) {}
    ~TransferWriter() = default;

    template <typename T>
    void value(const T& item) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* bytes = reinterpret_cast<const char*>(&item);
        buffer_.insert(buffer_.end(), bytes, bytes + sizeof item);
        if (buffer_.size() > (1u << 16)) flush();
    }
    void text(const std::string& item) {
        value(std::uint64_t(item.size()));
        bytes(item.data(), item.size());
    }
    void path(const std::filesystem::path& item) { text(item.string()); }
    template <typename T>
    void array(const std::vector<T>& items) {
        static_assert(std::is_trivially_copyable_v<T>);
        value(std::uint64_t(items.size()));
        bytes(items.data(), items.size() * sizeof(T));
    }
    void bytes(const void* data, std::size_t count) {
        if (count < (1u << 16)) {
            const auto* first = static_cast<const char*>(data);
            buffer_.insert(buffer_.end(), first, first + count);
            return;
        }
        flush();
        writeAll(data, count);
    }
    void flush() {
        writeAll(buffer_.data(), buffer_.size());
        buffer_.clear();
    }
    std::uint64_t written() const { return written_ + buffer_.size(); }

private:
    void writeAll(const void* data, std::size_t count) {
        const auto* next = static_cast<const char*>(data);
        while (count > 0) {
            const ssize_t done = ::write(fd_, next, count);
            if (done < 0 && errno == EINTR) continue;
            if (done <= 0) failSystem("write the series");
            next += done;
            count -= std::size_t(done);
            written_ += std::uint64_t(done);
        }
    }

    int fd_;
    std::vector<char> buffer_;
    std::uint64_t written_ = 0;
};

class TransferReader {
public:
    TransferReader(int fd, std::uint64_t size) : fd_(fd), size_(size) {}

    template <typename T>
    T value() {
        static_assert(std::is_trivially_copyable_v<T>);
        T item{};
        bytes(&item, sizeof item);
        return item;
    }
    std::string text() {
        std::string item(count(1), '\0');
        bytes(item.data(), item.size());
        return item;
    }
    std::filesystem::path path() { return text(); }
    // A large array's pages are given back once copied: the reader then holds one copy of it.
    template <typename T>
    std::vector<T> array() {
        std::vector<T> items(count(sizeof(T)));
        const std::uint64_t start = offset_;
        bytes(items.data(), items.size() * sizeof(T));
        releasePages(start, offset_);
        return items;
    }

private:
    // An element count, checked against what is left so a broken stream cannot ask for memory.
    std::size_t count(std::size_t elementBytes) {
        const auto items = value<std::uint64_t>();
        if (elementBytes > 0 && items > (size_ - offset_) / elementBytes)
            throw std::runtime_error("series transfer: a count runs past the end of the stream");
        return std::size_t(items);
    }
    void bytes(void* data, std::size_t count) {
        if (count > size_ - offset_) throw std::runtime_error("series transfer: the stream ends early");
        auto* next = static_cast<char*>(data);
        while (count > 0) {
            const ssize_t done = ::pread(fd_, next, count, off_t(offset_));
            if (done < 0 && errno == EINTR) continue;
            if (done <= 0) failSystem("read the series");
            next += done;
            count -= std::size_t(done);
            offset_ += std::uint64_t(done);
        }
    }
    void releasePages(std::uint64_t begin, std::uint64_t end) {
        const std::uint64_t page = std::uint64_t(::sysconf(_SC_PAGESIZE));
        const std::uint64_t first = (begin + page - 1) / page * page;
        const std::uint64_t last = end / page * page;
        // Best effort: a file that cannot punch holes keeps its pages until it is closed.
        if (last > first)
            (void)::fallocate(fd_, FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE, off_t(first), off_t(last - first));
    }

    int fd_;
    std::uint64_t size_;
    std::uint64_t offset_ = 0;
};

void writeAxes(TransferWriter& out, const Series& series) {
    for (const SpatialAxis& axis : series.axes) {
        out.text(axis.name);
        out.text(axis.unit);
        out.value(axis.direction);
        out.value(axis.negated);
    }
    out.value(series.time.unit);
    // Field by field: the struct's padding bytes are not part of the value.
    const CalendarDate date = series.time.reference.value_or(CalendarDate{});
    out.value(series.time.reference.has_value());
    out.value(std::array<int, 5>{date.year, date.month, date.day, date.hour, date.minute});
    out.value(date.second);
    out.value(series.time.calendar);
    out.value(series.time.climatology);
}

void readAxes(TransferReader& in, Series& series) {
    for (SpatialAxis& axis : series.axes) {
        axis.name = in.text();
        axis.unit = in.text();
        axis.direction = in.value<AxisDirection>();
        axis.negated = in.value<bool>();
    }
    series.time.unit = in.value<TimeUnit>();
    const bool hasReference = in.value<bool>();
    const auto fields = in.value<std::array<int, 5>>();
    const auto second = in.value<double>();
    if (hasReference)
        series.time.reference = CalendarDate{fields[0], fields[1], fields[2], fields[3], fields[4], second};
    series.time.calendar = in.value<Calendar>();
    series.time.climatology = in.value<bool>();
}

// Structured grids of several time-steps often share one node array: written once, shared again.
struct SharedNodes {
    std::vector<const std::vector<glm::vec3>*> written;
    std::vector<std::shared_ptr<const std::vector<glm::vec3>>> read;
};

void writeGrid(TransferWriter& out, const Grid& grid, SharedNodes& shared) {
    out.value(std::uint8_t(grid.index()));
    if (const auto* rectilinear = std::get_if<RectilinearGrid>(&grid)) {
        out.value(rectilinear->dims);
        out.value(rectilinear->spacing);
        for (const auto& positions : rectilinear->axisPositions) out.array(positions);
    } else if (const auto* structured = std::get_if<StructuredGrid>(&grid)) {
        out.value(structured->dims);
        out.path(structured->coordinatesFile);
        out.value(structured->localLower);
        out.value(structured->localUpper);
        out.value(structured->finestEdge);
        const std::vector<glm::vec3>* nodes = structured->nodes.get();
        std::uint64_t index = 0;
        while (index < shared.written.size() && shared.written[index] != nodes) ++index;
        out.value(index);
        if (index == shared.written.size()) {
            shared.written.push_back(nodes);
            out.array(nodes ? *nodes : std::vector<glm::vec3>{});
        }
    } else {
        const BeamGrid& beam = std::get<BeamGrid>(grid);
        out.value(beam.dims);
        out.array(beam.azimuthDeg);
        out.array(beam.elevationDeg);
        out.value(beam.minRange);
        out.value(beam.maxRange);
    }
}

Grid readGrid(TransferReader& in, SharedNodes& shared) {
    const auto kind = in.value<std::uint8_t>();
    if (kind == 0) {
        RectilinearGrid grid;
        grid.dims = in.value<glm::ivec3>();
        grid.spacing = in.value<glm::dvec3>();
        for (auto& positions : grid.axisPositions) positions = in.array<double>();
        return grid;
    }
    if (kind == 1) {
        StructuredGrid grid;
        grid.dims = in.value<glm::ivec3>();
        grid.coordinatesFile = in.path();
        grid.localLower = in.value<glm::dvec3>();
        grid.localUpper = in.value<glm::dvec3>();
        grid.finestEdge = in.value<double>();
        const auto index = in.value<std::uint64_t>();
        if (index > shared.read.size()) throw std::runtime_error("series transfer: a node array out of order");
        if (index == shared.read.size())
            shared.read.push_back(std::make_shared<const std::vector<glm::vec3>>(in.array<glm::vec3>()));
        grid.nodes = shared.read[index];
        return grid;
    }
    if (kind != 2) throw std::runtime_error("series transfer: unknown grid kind " + std::to_string(kind));
    BeamGrid grid;
    grid.dims = in.value<glm::ivec3>();
    grid.azimuthDeg = in.array<double>();
    grid.elevationDeg = in.array<double>();
    grid.minRange = in.value<double>();
    grid.maxRange = in.value<double>();
    return grid;
}

void writeStep(TransferWriter& out, TimeStep& step, SharedNodes& shared) {
    out.value(step.time);
    writeGrid(out, step.grid, shared);
    out.value(step.placement.origin);
    out.value(step.placement.rotation);
    out.value(step.sourceType);
    out.value(step.rawRange);
    out.path(step.valuesFile);
    out.path(step.maskFile);
    out.array(step.density);
    std::vector<float>().swap(step.density);
    out.value(step.mask.has_value());
    if (step.mask) {
        out.array(*step.mask);
        step.mask.reset();
    }
}

TimeStep readStep(TransferReader& in, SharedNodes& shared) {
    TimeStep step;
    step.time = in.value<double>();
    step.grid = readGrid(in, shared);
    step.placement.origin = in.value<glm::dvec3>();
    step.placement.rotation = in.value<glm::dquat>();
    step.sourceType = in.value<ValueType>();
    step.rawRange = in.value<std::array<double, 2>>();
    step.valuesFile = in.path();
    step.maskFile = in.path();
    step.density = in.array<float>();
    if (in.value<bool>()) step.mask = in.array<std::uint8_t>();
    return step;
}

}  // namespace

std::uint64_t writeSeries(int fd, Series&& series) {
    TransferWriter out(fd);
    out.value(kMagic);
    out.text(series.name);
    out.path(series.manifestPath);
    out.value(series.valueRange);
    out.text(series.valueUnit);
    out.value(series.precision);
    out.text(series.sourceFormat);
    out.value(std::uint64_t(series.readingNotes.size()));
    for (const std::string& note : series.readingNotes) out.text(note);
    writeAxes(out, series);
    out.value(std::uint64_t(series.steps.size()));
    SharedNodes shared;
    for (TimeStep& step : series.steps) writeStep(out, step, shared);
    out.flush();
    return out.written();
}

Series readSeries(int fd, std::uint64_t bytes) {
    TransferReader in(fd, bytes);
    if (in.value<std::uint64_t>() != kMagic) throw std::runtime_error("series transfer: not a series stream");
    Series series;
    series.name = in.text();
    series.manifestPath = in.path();
    series.valueRange = in.value<std::array<double, 2>>();
    series.valueUnit = in.text();
    series.precision = in.value<DensityPrecision>();
    series.sourceFormat = in.text();
    const auto notes = in.value<std::uint64_t>();
    for (std::uint64_t index = 0; index < notes; ++index) series.readingNotes.push_back(in.text());
    readAxes(in, series);
    const auto steps = in.value<std::uint64_t>();
    if (steps > bytes) throw std::runtime_error("series transfer: more time-steps than bytes");
    series.steps.reserve(std::size_t(steps));
    SharedNodes shared;
    for (std::uint64_t index = 0; index < steps; ++index) series.steps.push_back(readStep(in, shared));
    return series;
}

}  // namespace tstyles
