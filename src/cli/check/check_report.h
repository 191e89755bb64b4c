// The report of a `tstyles check` run: for every case that did not pass, its expected, actual and
// difference images; an HTML page showing them side by side; and a JUnit XML file for CI systems.
// Written into a folder beside the target and renamed over it when complete.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tstyles/image/image_comparison.h"

namespace tstyles::cli {

enum class CaseOutcome { Passed, Failed, MissingGolden, Updated };

struct CaseResult {
    std::string name;
    std::filesystem::path scene;
    CaseOutcome outcome = CaseOutcome::Passed;
    std::optional<ImageDifference> difference;  // none without a golden (or a golden of another size)
    std::vector<std::string> problems;          // thresholds exceeded, or what is missing
    double seconds = 0.0;
    // For the report of a case that did not pass.
    std::optional<Image> expected;
    std::optional<Image> actual;
};

// Checks first that `folder` can be replaced: it does not exist (it is made, with its parents), or
// holds a previous report (index.html, junit.xml, images) and nothing else. InputError otherwise.
void requireReplaceableReportFolder(const std::filesystem::path& folder);
void writeCheckReport(const std::filesystem::path& folder, const std::string& suiteName,
                      const std::vector<CaseResult>& results);

std::string toString(CaseOutcome outcome);  // "pass", "FAIL", "NO GOLDEN", "updated"

}  // namespace tstyles::cli
