// Baking transfer functions into lookup tables.
#include "tstyles/render/transfer_tables.h"

#include <algorithm>

#include "tstyles/render/shader_contract.h"

namespace tstyles {
namespace {

glm::vec4 toVec4(const ColorOpacity& value) { return glm::vec4(glm::vec3(value.color), float(value.opacity)); }

Texture createTable() {
    Texture table = Texture::create(GL_TEXTURE_1D);
    glTextureStorage1D(table.id(), 1, GL_RGBA32F, kTransferTableSize);
    table.setFilter(GL_LINEAR, GL_LINEAR);
    table.setClampToEdge();
    return table;
}

void upload(const Texture& table, const std::vector<glm::vec4>& entries) {
    glTextureSubImage1D(table.id(), 0, 0, kTransferTableSize, GL_RGBA, GL_FLOAT, entries.data());
}

}  // namespace

std::vector<glm::vec4> bakeTransferTable(const TransferFunction1D& function) {
    std::vector<glm::vec4> entries(kTransferTableSize);
    for (int i = 0; i < kTransferTableSize; ++i)
        entries[i] = toVec4(function.evaluate(double(i) / double(kTransferTableSize - 1)));
    return entries;
}

glm::vec2 visibleDensityRange(const std::vector<glm::vec4>& table) {
    const auto visible = [](const glm::vec4& entry) { return entry.a > 0.0f; };
    const auto first = std::find_if(table.begin(), table.end(), visible);
    if (first == table.end() || table.size() < 2) return {2.0f, -1.0f};
    const auto last = std::find_if(table.rbegin(), table.rend(), visible);
    const float step = 1.0f / float(table.size() - 1);
    // A lookup at x blends the entries either side of x (size - 1); x at least an entry and a half
    // below the first visible entry blends two transparent ones.
    const float low = (float(first - table.begin()) - 1.5f) * step;
    const float high = (float(table.rend() - last - 1) + 1.5f) * step;
    return {low, high};
}

bool opacityNeverFalls(const std::vector<glm::vec4>& table) {
    return std::is_sorted(table.begin(), table.end(),
                          [](const glm::vec4& a, const glm::vec4& b) { return a.a < b.a; });
}

std::vector<glm::vec4> bakeIndexTstf(const IndexTstf& tstf, std::size_t timeStepCount) {
    std::vector<glm::vec4> entries(timeStepCount);
    for (std::size_t step = 0; step < timeStepCount; ++step) entries[step] = toVec4(tstf.atStep(int(step)));
    return entries;
}

TransferTables::TransferTables()
    : stfTable_(createTable()), gradientTstfTable_(createTable()), indexTstfBuffer_(Buffer::create()) {}

bool TransferTables::update(const Stf& stf, const IndexTstf& indexTstf, const GradientTstf& gradientTstf,
                            std::size_t timeStepCount) {
    const bool stfChanged = !bakedStf_ || !(*bakedStf_ == stf);
    if (stfChanged) {
        stfEntries_ = bakeTransferTable(stf.curve);
        stfVisibleRange_ = visibleDensityRange(stfEntries_);
        stfOpacityRises_ = opacityNeverFalls(stfEntries_);
        upload(stfTable_, stfEntries_);
        bakedStf_ = stf;
    }
    if (!bakedGradientCurve_ || !(*bakedGradientCurve_ == gradientTstf.curve)) {
        upload(gradientTstfTable_, bakeTransferTable(gradientTstf.curve));
        bakedGradientCurve_ = gradientTstf.curve;
    }
    if (!bakedIndexTstf_ || !(*bakedIndexTstf_ == indexTstf) || bakedTimeStepCount_ != timeStepCount) {
        const auto entries = bakeIndexTstf(indexTstf, timeStepCount);
        indexTstfBuffer_.setData(std::as_bytes(std::span(entries)));
        bakedIndexTstf_ = indexTstf;
        bakedTimeStepCount_ = timeStepCount;
    }
    return stfChanged;
}

void TransferTables::bind() const {
    stfTable_.bindToUnit(contract::STF_UNIT);
    gradientTstfTable_.bindToUnit(contract::GRADIENT_TSTF_UNIT);
    indexTstfBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, contract::INDEX_TSTF_BUFFER);
}

}  // namespace tstyles
