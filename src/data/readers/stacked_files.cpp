// A list of single-volume files as one series: each file's reader is kept for its own step.
#include "stacked_files.h"

#include <memory>

#include "tstyles/core/errors.h"

namespace tstyles {

std::function<SourceSeries(const std::vector<std::filesystem::path>&, const ReadOptions&)> stackedFiles(
    SingleFileReader reader) {
    return [reader](const std::vector<std::filesystem::path>& files, const ReadOptions& options) {
        if (files.size() == 1) return reader(files.front(), options);
        auto parts = std::make_shared<std::vector<SourceSeries>>();
        SourceSeries stacked;
        stacked.file = files.front();
        for (const auto& file : files) {
            parts->push_back(reader(file, options));
            const SourceSeries& part = parts->back();
            if (part.steps.size() != 1)
                throwInputError(file, "",
                                "holds " + std::to_string(part.steps.size()) +
                                    " time-steps: a list of files must give one volume per file");
            SourceStep step = part.steps.front();
            step.time = double(stacked.steps.size());
            stacked.steps.push_back(step);
        }
        stacked.name = parts->front().name;
        stacked.format = parts->front().format + " (" + std::to_string(files.size()) + " files)";
        stacked.readStep = [parts](std::size_t index) { return (*parts)[index].readStep(0); };
        return stacked;
    };
}

}  // namespace tstyles
