// Beam grid geometry: the tangent-plane angles of a sample, the fan's enclosing mesh.
#include "tstyles/data/beam_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tstyles {
namespace {

double tangentOfDegrees(double degrees) { return std::tan(glm::radians(degrees)); }

glm::dvec3 directionOfDegrees(double azimuthDeg, double elevationDeg) {
    return glm::normalize(glm::dvec3(tangentOfDegrees(azimuthDeg), tangentOfDegrees(elevationDeg), 1.0));
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

// Adds the triangle (a, b, c), flipped if needed so that its normal agrees with `outward`.
void addOriented(std::vector<Triangle>& mesh, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                 const glm::dvec3& outward) {
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    if (glm::dot(normal, outward) >= 0.0)
        mesh.push_back({a, b, c});
    else
        mesh.push_back({a, c, b});
}

}  // namespace

glm::dvec3 beamDirection(double azimuthRad, double elevationRad) {
    return glm::normalize(glm::dvec3(std::tan(azimuthRad), std::tan(elevationRad), 1.0));
}

std::optional<double> fractionalBeamIndex(const std::vector<double>& anglesDeg, double angleDeg) {
    // Samples on the outermost beams must count as inside despite rounding in atan2.
    constexpr double kToleranceDeg = 1e-9;
    if (anglesDeg.size() < 2 || angleDeg < anglesDeg.front() - kToleranceDeg ||
        angleDeg > anglesDeg.back() + kToleranceDeg)
        return std::nullopt;
    angleDeg = std::clamp(angleDeg, anglesDeg.front(), anglesDeg.back());
    const auto upper = std::upper_bound(anglesDeg.begin(), anglesDeg.end(), angleDeg);
    const std::size_t next = std::min(std::size_t(upper - anglesDeg.begin()), anglesDeg.size() - 1);
    const std::size_t previous = next - 1;
    const double fraction = (angleDeg - anglesDeg[previous]) / (anglesDeg[next] - anglesDeg[previous]);
    return double(previous) + std::clamp(fraction, 0.0, 1.0);
}

std::optional<glm::dvec3> beamVoxel(const BeamGrid& grid, const glm::dvec3& local) {
    if (!(local.z > 0.0)) return std::nullopt;
    const double range = glm::length(local);
    const double tolerance = 1e-12 * grid.maxRange;  // samples on the near and far caps are inside
    if (range < grid.minRange - tolerance || range > grid.maxRange + tolerance) return std::nullopt;
    const auto across = fractionalBeamIndex(grid.azimuthDeg, glm::degrees(std::atan2(local.x, local.z)));
    const auto along = fractionalBeamIndex(grid.elevationDeg, glm::degrees(std::atan2(local.y, local.z)));
    if (!across || !along) return std::nullopt;
    return glm::dvec3(*across, *along, (range - grid.minRange) / grid.rangeSpacing());
}

glm::dvec3 beamSamplePosition(const BeamGrid& grid, int i, int j, int k) {
    const double range = grid.minRange + double(k) * grid.rangeSpacing();
    return range * directionOfDegrees(grid.azimuthDeg[std::size_t(i)], grid.elevationDeg[std::size_t(j)]);
}

std::vector<double> evenBeamAngles(double firstDeg, double lastDeg, int count) {
    std::vector<double> angles(std::size_t(std::max(count, 0)));
    for (int index = 0; index < count; ++index)
        angles[std::size_t(index)] = firstDeg + (lastDeg - firstDeg) * double(index) / double(count - 1);
    if (count >= 2) angles.back() = lastDeg;
    return angles;
}

bool areEvenBeamAngles(const std::vector<double>& anglesDeg) {
    if (anglesDeg.size() < 2) return true;
    const std::vector<double> even = evenBeamAngles(anglesDeg.front(), anglesDeg.back(), int(anglesDeg.size()));
    for (std::size_t index = 0; index < even.size(); ++index)
        if (std::abs(even[index] - anglesDeg[index]) > 1e-9) return false;
    return true;
}

std::vector<Triangle> beamFanBoundary(const BeamGrid& grid, int subdivisions) {
    const int n = std::max(subdivisions, 1);
    const double azimuth0 = grid.azimuthDeg.front(), azimuth1 = grid.azimuthDeg.back();
    const double elevation0 = grid.elevationDeg.front(), elevation1 = grid.elevationDeg.back();
    // Directions of the cap's lattice, (n + 1)^2 of them, evenly spread in angle.
    std::vector<glm::dvec3> directions;
    for (int v = 0; v <= n; ++v)
        for (int u = 0; u <= n; ++u)
            directions.push_back(directionOfDegrees(azimuth0 + (azimuth1 - azimuth0) * u / n,
                                                    elevation0 + (elevation1 - elevation0) * v / n));
    auto direction = [&](int u, int v) { return directions[std::size_t(v * (n + 1) + u)]; };

    // A triangle with its corners on a sphere of radius R comes no closer to the centre than
    // R cos(a), a the largest angle between its corners; pushing the far cap out to
    // maxRange / cos(a) keeps every facet outside the true far cap.
    double widest = 0.0;
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n; ++u)
            widest = std::max({widest, angleBetween(direction(u, v), direction(u + 1, v + 1)),
                               angleBetween(direction(u + 1, v), direction(u, v + 1))});
    const double farRadius = grid.maxRange / std::cos(widest);
    const double nearRadius = grid.minRange;  // chords of the near cap lie inside it: conservative

    std::vector<Triangle> mesh;
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n; ++u) {
            const glm::dvec3 a = direction(u, v), b = direction(u + 1, v), c = direction(u + 1, v + 1),
                             d = direction(u, v + 1);
            const glm::dvec3 outward = a + b + c + d;
            addOriented(mesh, farRadius * a, farRadius * b, farRadius * c, outward);
            addOriented(mesh, farRadius * a, farRadius * c, farRadius * d, outward);
            if (nearRadius > 0.0) {
                addOriented(mesh, nearRadius * a, nearRadius * b, nearRadius * c, -outward);
                addOriented(mesh, nearRadius * a, nearRadius * c, nearRadius * d, -outward);
            }
        }
    // The four sides: strips from the near edge to the far edge of the cap's border.
    const glm::dvec3 inside = directionOfDegrees(0.5 * (azimuth0 + azimuth1), 0.5 * (elevation0 + elevation1));
    auto addSide = [&](auto borderDirection) {
        for (int s = 0; s < n; ++s) {
            const glm::dvec3 a = borderDirection(s), b = borderDirection(s + 1);
            const glm::dvec3 outward = glm::cross(a, b) * (glm::dot(glm::cross(a, b), inside) > 0.0 ? -1.0 : 1.0);
            addOriented(mesh, nearRadius * a, nearRadius * b, farRadius * b, outward);
            addOriented(mesh, nearRadius * a, farRadius * b, farRadius * a, outward);
        }
    };
    addSide([&](int s) { return direction(0, s); });
    addSide([&](int s) { return direction(n, s); });
    addSide([&](int s) { return direction(s, 0); });
    addSide([&](int s) { return direction(s, n); });
    return mesh;
}

double beamFinestSpacing(const BeamGrid& grid) {
    double finest = grid.rangeSpacing();
    auto arcs = [&](const std::vector<double>& anglesDeg, bool isAzimuth) {
        for (std::size_t index = 0; index + 1 < anglesDeg.size(); ++index) {
            const glm::dvec3 a = isAzimuth ? directionOfDegrees(anglesDeg[index], 0.0)
                                           : directionOfDegrees(0.0, anglesDeg[index]);
            const glm::dvec3 b = isAzimuth ? directionOfDegrees(anglesDeg[index + 1], 0.0)
                                           : directionOfDegrees(0.0, anglesDeg[index + 1]);
            finest = std::min(finest, angleBetween(a, b) * grid.maxRange);
        }
    };
    arcs(grid.azimuthDeg, true);
    arcs(grid.elevationDeg, false);
    return finest;
}

}  // namespace tstyles
