// Sort-last compositing: the frames that processes rendered of their blocks, merged in visibility
// order into one. The MPI exchange is radix-k (Peterka, Goodell, Ross, Shen and Thakur, "A
// configurable algorithm for parallel image-compositing applications", SC 2009): in round i, the
// k_i processes whose blocks are slabs of one parent block (BlockDecomposition) each take 1/k_i of
// the pixels they hold and composite that part of the parent's image from all k_i; with every
// k_i = 2 it is binary swap. Pixels are premultiplied RGBA, rows top to bottom.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "tstyles/distributed/block_decomposition.h"
#include "tstyles/distributed/mpi_session.h"
#include "tstyles/image/image.h"

namespace tstyles {

// Pixels [begin, end) of a frame in row order.
struct PixelSpan {
    std::size_t begin = 0;
    std::size_t end = 0;
    std::size_t size() const { return end - begin; }
    bool operator==(const PixelSpan&) const = default;
};

// Part `index` of `parts` near-equal consecutive parts of `span`.
PixelSpan partOf(PixelSpan span, int parts, int index);
// The pixels that `rank` holds after the last round (radix-k): the spans of all ranks tile the frame.
PixelSpan finalSpan(const BlockDecomposition& blocks, int rank, std::size_t pixelCount);

// The direction of each pixel's viewing ray (ray.glsl's rayForPixel, on the CPU): along a cut
// axis, a ray running toward + meets the lower slab first.
class PixelRays {
public:
    PixelRays(const glm::dmat4& inverseViewProjection, glm::ivec2 size);
    // A vector along the ray of pixel `pixel` in row order, of arbitrary positive length (only
    // signs are used): the near and far points of the pixel are affine in its position before the
    // perspective division, so their difference after it has the sign of far * near.w - near * far.w.
    glm::dvec3 direction(std::size_t pixel) const;

private:
    glm::dmat4 inverseViewProjection_;
    glm::ivec2 size_;
};

// `front` over `back`, premultiplied: front + (1 - front.a) back.
inline glm::vec4 over(const glm::vec4& front, const glm::vec4& back) { return front + (1.0f - front.a) * back; }

// Composites `pieces[j]` (the pixels of `span` from slab j of a parent block cut along `axis`)
// into `result`, per pixel in the order the pixel's ray meets the slabs.
void compositeSlabs(const std::vector<const float*>& pieces, PixelSpan span, int axis, const PixelRays& rays,
                    float* result);

// Reference compositing for tests: every block's whole frame, merged per pixel in the order the
// pixel's ray enters the blocks (a ray meets non-overlapping boxes in order of entry).
Image compositeInEntryOrder(const std::vector<Image>& frames, const BlockDecomposition& blocks,
                            const glm::dmat4& inverseViewProjection);

// Radix-k over the processes of `mpi` (collective): `local` is this process's frame of its block of
// `blocks`, transparent where its block is not seen. Returns the composited frame on process 0
// and an empty image on the others.
Image compositeSortLast(const MpiSession& mpi, const BlockDecomposition& blocks, const Image& local,
                        const glm::dmat4& inverseViewProjection);

}  // namespace tstyles
