// Beam angles and their bucket lookup, flattened for the GPU.
#include "tstyles/render/beam_angle_table.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "tstyles/core/errors.h"

namespace tstyles {

int appendBeamAngleRun(const std::vector<double>& anglesDeg, std::vector<float>& table,
                       const std::filesystem::path& file, const std::string& field) {
    const int first = int(table.size());
    const int count = int(anglesDeg.size());
    for (const double angle : anglesDeg) table.push_back(float(glm::radians(angle)));
    // Bucket bounds are taken from the stored (float) angles, which are what the shader compares.
    const auto angle = [&](int index) { return double(table[std::size_t(first + index)]); };
    const double span = angle(count - 1) - angle(0);
    double narrowestGap = span;
    for (int index = 1; index < count; ++index) narrowestGap = std::min(narrowestGap, angle(index) - angle(index - 1));
    const double wanted = narrowestGap > 0.0 ? std::ceil(2.0 * span / narrowestGap) : double(kMaxBeamBuckets) + 1.0;
    if (wanted > double(kMaxBeamBuckets))
        throwInputError(file, field,
                        "neighbouring beams are too close together for the renderer's angle lookup (the "
                        "narrowest gap must be at least 1/" +
                            std::to_string(kMaxBeamBuckets / 2) + " of the fan's width)");
    const int buckets = std::max(1, int(wanted));
    const double width = span / buckets;
    table.push_back(float(1.0 / width));
    table.push_back(float(buckets));
    const int lastCell = count - 2;
    int lower = 0;
    for (int bucket = 0; bucket < buckets; ++bucket) {
        while (lower < lastCell && angle(lower + 1) <= angle(0) + bucket * width) ++lower;
        table.push_back(float(lower));
    }
    return first;
}

float lookUpBeamIndex(const std::vector<float>& table, int first, int count, float angleRad) {
    const auto at = [&](int index) { return table[std::size_t(index)]; };
    const float firstAngle = at(first);
    if (angleRad < firstAngle || angleRad > at(first + count - 1)) return -1.0f;
    const int lookup = first + count;
    const int buckets = int(at(lookup + 1));
    const int bucket = std::clamp(int((angleRad - firstAngle) * at(lookup)), 0, buckets - 1);
    // The bucket's lower beam, or its neighbour where float rounding put the angle in the next or
    // the previous bucket: one step at most, since two neighbouring buckets together are at most
    // the narrowest gap between beams wide.
    int low = int(at(lookup + 2 + bucket));
    if (low < count - 2 && at(first + low + 1) <= angleRad)
        ++low;
    else if (low > 0 && at(first + low) > angleRad)
        --low;
    const float lowAngle = at(first + low);
    const float highAngle = at(first + low + 1);
    return float(low) + std::clamp((angleRad - lowAngle) / (highAngle - lowAngle), 0.0f, 1.0f);
}

}  // namespace tstyles
