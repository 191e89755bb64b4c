// MPI start and stop, and failing together (mpi_session.h).
#include "tstyles/distributed/mpi_session.h"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <new>
#include <vector>

#include "tstyles/core/errors.h"

namespace tstyles {
namespace {

// Exit codes as the command line gives them (src/cli/commands.h): 0 fine, 1 internal, 2 bad
// input, 3 no OpenGL. Where processes fail differently, the larger code is the one reported: a
// machine without OpenGL explains the others' failures, bad input explains internal errors.
enum FailureKind : int { kNoFailure = 0, kInternal = 1, kBadInput = 2, kNoOpenGl = 3 };

// Point-to-point messages: a length, then the bytes in pieces that MPI's int counts can hold (an
// image of 16384x16384 float RGBA is 4 GiB).
constexpr int kBytesTag = 7301;
constexpr std::uint64_t kPieceBytes = std::uint64_t(1) << 30;

}  // namespace

MpiSession::MpiSession() {
    int initialized = 0;
    MPI_Initialized(&initialized);
    if (!initialized) MPI_Init(nullptr, nullptr);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &processCount_);
}

MpiSession::~MpiSession() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
}

void MpiSession::together(const std::string& step, const std::function<void()>& work) const {
    int code = kNoFailure;
    std::string message;
    try {
        work();
    } catch (const InputError& error) {
        code = kBadInput;
        message = error.what();
    } catch (const GlUnavailableError& error) {
        code = kNoOpenGl;
        message = error.what();
    } catch (const std::bad_alloc&) {
        code = kBadInput;
        message = "not enough memory for this process's block while " + step;
    } catch (const std::exception& error) {
        code = kInternal;
        message = error.what();
    }
    if (code != kNoFailure && message.empty()) message = "failed while " + step;
    int gravest = code;
    MPI_Allreduce(MPI_IN_PLACE, &gravest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (gravest == 0) return;

    // Every process's message to process 0, which reports them all.
    const int length = int(message.size());
    std::vector<int> lengths(std::size_t(processCount_), 0);
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::vector<int> offsets(std::size_t(processCount_), 0);
    int total = 0;
    for (std::size_t process = 0; process < lengths.size(); ++process) {
        offsets[process] = total;
        total += lengths[process];
    }
    std::string all(std::size_t(total), '\0');
    MPI_Gatherv(message.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
                MPI_COMM_WORLD);
    const int exitCode = gravest;
    if (rank_ != 0) throw FailedOnAnotherProcess();

    std::string report;
    int failing = 0;
    for (std::size_t process = 0; process < lengths.size(); ++process) {
        if (lengths[process] == 0) continue;
        if (failing++ > 0) report += "\n";
        report += "process " + std::to_string(process) + " of " + std::to_string(processCount_) + ": " +
                  all.substr(std::size_t(offsets[process]), std::size_t(lengths[process]));
    }
    if (exitCode == kNoOpenGl) throw GlUnavailableError(report);
    if (exitCode == kBadInput) throw InputError(report);
    throw std::runtime_error(report);
}

double MpiSession::maximum(double value) const {
    MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return value;
}

std::vector<double> MpiSession::sum(std::vector<double> values) const {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    return values;
}

std::vector<double> MpiSession::minimum(std::vector<double> values) const {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    return values;
}

std::vector<double> MpiSession::maximum(std::vector<double> values) const {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return values;
}

std::vector<double> MpiSession::gathered(const std::vector<double>& values) const {
    const int count = int(values.size());
    std::vector<int> counts(std::size_t(processCount_), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::vector<int> offsets(std::size_t(processCount_), 0);
    int total = 0;
    for (std::size_t process = 0; process < counts.size(); ++process) {
        offsets[process] = total;
        total += counts[process];
    }
    std::vector<double> all(static_cast<std::size_t>(total));
    MPI_Allgatherv(values.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                   MPI_COMM_WORLD);
    return all;
}

void MpiSession::send(int process, const std::vector<std::uint8_t>& bytes) const {
    std::uint64_t length = bytes.size();
    MPI_Send(&length, 1, MPI_UINT64_T, process, kBytesTag, MPI_COMM_WORLD);
    for (std::uint64_t offset = 0; offset < length; offset += kPieceBytes) {
        const int piece = int(std::min(kPieceBytes, length - offset));
        MPI_Send(bytes.data() + offset, piece, MPI_BYTE, process, kBytesTag, MPI_COMM_WORLD);
    }
}

std::vector<std::uint8_t> MpiSession::receive(int process) const {
    std::uint64_t length = 0;
    MPI_Recv(&length, 1, MPI_UINT64_T, process, kBytesTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    std::vector<std::uint8_t> bytes(length);
    for (std::uint64_t offset = 0; offset < length; offset += kPieceBytes) {
        const int piece = int(std::min(kPieceBytes, length - offset));
        MPI_Recv(bytes.data() + offset, piece, MPI_BYTE, process, kBytesTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    }
    return bytes;
}

}  // namespace tstyles
