// CaseResult to CBOR and back (check_result_message.h). Doubles and floats keep every bit: CBOR
// stores them as IEEE numbers, and the images as their raw bytes.
#include "check_result_message.h"

#include <cstring>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace tstyles::cli {
namespace {

using nlohmann::json;

json vec4ToJson(const glm::vec4& value) { return json::array({value.r, value.g, value.b, value.a}); }

glm::vec4 vec4FromJson(const json& value) {
    return {value.at(0).get<float>(), value.at(1).get<float>(), value.at(2).get<float>(), value.at(3).get<float>()};
}

json differenceToJson(const ImageDifference& difference) {
    json worst = json::array();
    for (const WorstPixel& pixel : difference.worstPixels)
        worst.push_back({{"x", pixel.position.x},
                         {"y", pixel.position.y},
                         {"delta", pixel.delta},
                         {"expected", vec4ToJson(pixel.expected)},
                         {"actual", vec4ToJson(pixel.actual)}});
    return {{"max_channel_delta", difference.maxChannelDelta},
            {"max_delta", difference.maxDelta},
            {"mean_delta", difference.meanDelta},
            {"failing_fraction", difference.failingFraction},
            {"ssim", difference.ssim},
            {"worst_pixels", worst}};
}

ImageDifference differenceFromJson(const json& value) {
    ImageDifference difference;
    difference.maxChannelDelta = value.at("max_channel_delta").get<std::array<int, 4>>();
    difference.maxDelta = value.at("max_delta").get<int>();
    difference.meanDelta = value.at("mean_delta").get<double>();
    difference.failingFraction = value.at("failing_fraction").get<double>();
    difference.ssim = value.at("ssim").get<double>();
    for (const json& pixel : value.at("worst_pixels"))
        difference.worstPixels.push_back({{pixel.at("x").get<int>(), pixel.at("y").get<int>()},
                                          pixel.at("delta").get<int>(),
                                          vec4FromJson(pixel.at("expected")),
                                          vec4FromJson(pixel.at("actual"))});
    return difference;
}

json imageToJson(const Image& image) {
    std::vector<std::uint8_t> bytes(image.rgba.size() * sizeof(float));
    std::memcpy(bytes.data(), image.rgba.data(), bytes.size());
    return {{"width", image.width}, {"height", image.height}, {"rgba", json::binary(std::move(bytes))}};
}

Image imageFromJson(const json& value) {
    Image image(value.at("width").get<int>(), value.at("height").get<int>());
    const std::vector<std::uint8_t>& bytes = value.at("rgba").get_binary();
    if (bytes.size() != image.rgba.size() * sizeof(float))
        throw std::runtime_error("a case result's image holds " + std::to_string(bytes.size()) + " bytes, not " +
                                 std::to_string(image.rgba.size() * sizeof(float)));
    std::memcpy(image.rgba.data(), bytes.data(), bytes.size());
    return image;
}

}  // namespace

std::vector<std::uint8_t> encodeCaseResult(const CaseResult& result) {
    json message = {{"name", result.name},
                    {"scene", result.scene.string()},
                    {"outcome", int(result.outcome)},
                    {"problems", result.problems},
                    {"seconds", result.seconds}};
    if (result.difference) message["difference"] = differenceToJson(*result.difference);
    if (result.expected) message["expected"] = imageToJson(*result.expected);
    if (result.actual) message["actual"] = imageToJson(*result.actual);
    return json::to_cbor(message);
}

CaseResult decodeCaseResult(const std::vector<std::uint8_t>& bytes) {
    try {
        const json message = json::from_cbor(bytes);
        CaseResult result{message.at("name").get<std::string>(), message.at("scene").get<std::string>()};
        result.outcome = CaseOutcome(message.at("outcome").get<int>());
        result.problems = message.at("problems").get<std::vector<std::string>>();
        result.seconds = message.at("seconds").get<double>();
        if (message.contains("difference")) result.difference = differenceFromJson(message.at("difference"));
        if (message.contains("expected")) result.expected = imageFromJson(message.at("expected"));
        if (message.contains("actual")) result.actual = imageFromJson(message.at("actual"));
        return result;
    } catch (const json::exception& error) {
        throw std::runtime_error(std::string("a case result from another process cannot be read: ") + error.what());
    }
}

}  // namespace tstyles::cli
