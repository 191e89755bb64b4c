// Merging block frames in visibility order (sort_last_compositing.h): the parts without MPI.
#include "tstyles/distributed/sort_last_compositing.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace tstyles {

PixelSpan partOf(PixelSpan span, int parts, int index) {
    const std::size_t count = span.size();
    const auto boundary = [&](int part) { return span.begin + count * std::size_t(part) / std::size_t(parts); };
    return {boundary(index), boundary(index + 1)};
}

PixelSpan finalSpan(const BlockDecomposition& blocks, int rank, std::size_t pixelCount) {
    PixelSpan span{0, pixelCount};
    for (std::size_t level = 0; level < blocks.factors().size(); ++level)
        span = partOf(span, blocks.factors()[level], blocks.digit(rank, int(level)));
    return span;
}

PixelRays::PixelRays(const glm::dmat4& inverseViewProjection, glm::ivec2 size)
    : inverseViewProjection_(inverseViewProjection), size_(size) {}

glm::dvec3 PixelRays::direction(std::size_t pixel) const {
    // Row order is top to bottom; OpenGL's window rows count from the bottom.
    const double column = double(pixel % std::size_t(size_.x)) + 0.5;
    const double row = double(size_.y - 1 - int(pixel / std::size_t(size_.x))) + 0.5;
    const glm::dvec2 ndc = glm::dvec2(column, row) / glm::dvec2(size_) * 2.0 - 1.0;
    const glm::dmat4& m = inverseViewProjection_;
    const glm::dvec4 onScreen = m[0] * ndc.x + m[1] * ndc.y + m[3];
    const glm::dvec4 nearPoint = onScreen - m[2];
    const glm::dvec4 farPoint = onScreen + m[2];
    // far / far.w - near / near.w, times near.w * far.w (positive: both points are in front of the eye).
    return glm::dvec3(farPoint) * nearPoint.w - glm::dvec3(nearPoint) * farPoint.w;
}

void compositeSlabs(const std::vector<const float*>& pieces, PixelSpan span, int axis, const PixelRays& rays,
                    float* result) {
    const int slabs = int(pieces.size());
    for (std::size_t offset = 0; offset < span.size(); ++offset) {
        const bool towardUpper = rays.direction(span.begin + offset)[axis] >= 0.0;
        glm::vec4 accumulated(0.0f);
        for (int order = 0; order < slabs; ++order) {
            const float* piece = pieces[std::size_t(towardUpper ? order : slabs - 1 - order)] + offset * 4;
            accumulated = over(accumulated, glm::vec4(piece[0], piece[1], piece[2], piece[3]));
        }
        std::copy_n(&accumulated.x, 4, result + offset * 4);
    }
}

namespace {

// Where the ray of `rays`' pixel enters `box` (its origin on the near plane): +infinity if it
// misses.
double entryDistance(const glm::dvec3& origin, const glm::dvec3& direction, const Bounds& box) {
    double nearest = -std::numeric_limits<double>::infinity();
    double farthest = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0.0) {
            if (origin[axis] < box.lower[axis] || origin[axis] > box.upper[axis])
                return std::numeric_limits<double>::infinity();
            continue;
        }
        const double toLower = (box.lower[axis] - origin[axis]) / direction[axis];
        const double toUpper = (box.upper[axis] - origin[axis]) / direction[axis];
        nearest = std::max(nearest, std::min(toLower, toUpper));
        farthest = std::min(farthest, std::max(toLower, toUpper));
    }
    return nearest <= farthest ? nearest : std::numeric_limits<double>::infinity();
}

}  // namespace

Image compositeInEntryOrder(const std::vector<Image>& frames, const BlockDecomposition& blocks,
                            const glm::dmat4& inverseViewProjection) {
    const Image& first = frames.at(0);
    Image result(first.width, first.height);
    std::vector<int> order(frames.size());
    std::vector<double> entries(frames.size());
    for (int y = 0; y < first.height; ++y)
        for (int x = 0; x < first.width; ++x) {
            const glm::dvec2 ndc = (glm::dvec2(x, first.height - 1 - y) + 0.5) / glm::dvec2(first.width, first.height) * 2.0 - 1.0;
            const glm::dvec4 nearPoint = inverseViewProjection * glm::dvec4(ndc, -1.0, 1.0);
            const glm::dvec4 farPoint = inverseViewProjection * glm::dvec4(ndc, 1.0, 1.0);
            const glm::dvec3 origin = glm::dvec3(nearPoint) / nearPoint.w;
            const glm::dvec3 direction = glm::dvec3(farPoint) / farPoint.w - origin;
            for (std::size_t block = 0; block < frames.size(); ++block)
                entries[block] = entryDistance(origin, direction, blocks.block(int(block)));
            std::iota(order.begin(), order.end(), 0);
            std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return entries[std::size_t(a)] < entries[std::size_t(b)]; });
            glm::vec4 accumulated(0.0f);
            for (int block : order) accumulated = over(accumulated, frames[std::size_t(block)].at(x, y));
            result.set(x, y, accumulated);
        }
    return result;
}

}  // namespace tstyles
