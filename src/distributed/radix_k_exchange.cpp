// Radix-k compositing over MPI (sort_last_compositing.h, compositeSortLast).
#include <mpi.h>

#include <algorithm>

#include "tstyles/distributed/sort_last_compositing.h"

namespace tstyles {

Image compositeSortLast(const MpiSession& mpi, const BlockDecomposition& blocks, const Image& local,
                        const glm::dmat4& inverseViewProjection) {
    const std::size_t pixelCount = std::size_t(local.width) * std::size_t(local.height);
    const PixelRays rays(inverseViewProjection, {local.width, local.height});
    const int rank = mpi.rank();
    // The pixels this process holds, composited over the blocks merged so far.
    PixelSpan span{0, pixelCount};
    std::vector<float> held = local.rgba;
    for (std::size_t level = 0; level < blocks.factors().size(); ++level) {
        const int slabs = blocks.factors()[level];
        const int own = blocks.digit(rank, int(level));
        std::vector<std::vector<float>> received(static_cast<std::size_t>(slabs));
        std::vector<const float*> pieces(std::size_t(slabs), nullptr);
        std::vector<MPI_Request> requests;
        for (int slab = 0; slab < slabs; ++slab) {
            const PixelSpan part = partOf(span, slabs, slab);
            const float* partOfHeld = held.data() + (part.begin - span.begin) * 4;
            if (slab == own) {
                pieces[std::size_t(slab)] = partOfHeld;
                continue;
            }
            const int partner = blocks.rankWithDigit(rank, int(level), slab);
            // Send the partner its part of what this process holds; receive this process's part
            // from the partner.
            const PixelSpan mine = partOf(span, slabs, own);
            std::vector<float>& buffer = received[std::size_t(slab)];
            buffer.resize(mine.size() * 4);
            requests.emplace_back();
            MPI_Irecv(buffer.data(), int(buffer.size()), MPI_FLOAT, partner, int(level), MPI_COMM_WORLD,
                      &requests.back());
            requests.emplace_back();
            MPI_Isend(partOfHeld, int(part.size() * 4), MPI_FLOAT, partner, int(level), MPI_COMM_WORLD,
                      &requests.back());
            pieces[std::size_t(slab)] = buffer.data();
        }
        MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
        const PixelSpan mine = partOf(span, slabs, own);
        std::vector<float> merged(mine.size() * 4);
        compositeSlabs(pieces, mine, blocks.splitAxis(rank, int(level)), rays, merged.data());
        held = std::move(merged);
        span = mine;
    }

    // Gather the parts onto process 0; they tile the frame.
    std::vector<int> counts;
    std::vector<int> offsets;
    Image frame;
    if (mpi.isFirst()) {
        frame = Image(local.width, local.height);
        for (int process = 0; process < mpi.processCount(); ++process) {
            const PixelSpan part = finalSpan(blocks, process, pixelCount);
            counts.push_back(int(part.size() * 4));
            offsets.push_back(int(part.begin * 4));
        }
    }
    MPI_Gatherv(held.data(), int(held.size()), MPI_FLOAT, frame.rgba.data(), counts.data(), offsets.data(),
                MPI_FLOAT, 0, MPI_COMM_WORLD);
    return frame;
}

}  // namespace tstyles
