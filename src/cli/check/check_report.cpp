// HTML and JUnit XML reports of check runs, with the images of failing cases.
#include "check_report.h"

#include <fstream>
#include <sstream>
#include <system_error>

#include <unistd.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/user_paths.h"
#include "tstyles/image/image_io.h"

namespace tstyles::cli {
namespace {

namespace fs = std::filesystem;

std::string escaped(const std::string& text) {
    std::string result;
    for (const char c : text) {
        switch (c) {
            case '&': result += "&amp;"; break;
            case '<': result += "&lt;"; break;
            case '>': result += "&gt;"; break;
            case '"': result += "&quot;"; break;
            case '\'': result += "&apos;"; break;
            default: result += c;
        }
    }
    return result;
}

bool passed(const CaseResult& result) {
    return result.outcome == CaseOutcome::Passed || result.outcome == CaseOutcome::Updated;
}

std::string figures(const CaseResult& result) {
    return result.difference ? describe(*result.difference) : std::string("no comparison");
}

std::string junitXml(const std::string& suiteName, const std::vector<CaseResult>& results) {
    int failures = 0;
    int errors = 0;
    double seconds = 0.0;
    for (const CaseResult& result : results) {
        failures += result.outcome == CaseOutcome::Failed;
        errors += result.outcome == CaseOutcome::MissingGolden;
        seconds += result.seconds;
    }
    std::ostringstream xml;
    xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<testsuites name=\"tstyles check\" tests=\"" << results.size() << "\" failures=\"" << failures
        << "\" errors=\"" << errors << "\" time=\"" << seconds << "\">\n"
        << "  <testsuite name=\"" << escaped(suiteName) << "\" tests=\"" << results.size() << "\" failures=\""
        << failures << "\" errors=\"" << errors << "\" skipped=\"0\" time=\"" << seconds << "\">\n";
    for (const CaseResult& result : results) {
        xml << "    <testcase classname=\"" << escaped(suiteName) << "\" name=\"" << escaped(result.name) << "\" time=\""
            << result.seconds << "\"";
        if (passed(result)) {
            xml << "/>\n";
            continue;
        }
        std::string message;
        for (const std::string& problem : result.problems) message += (message.empty() ? "" : "; ") + problem;
        const char* element = result.outcome == CaseOutcome::Failed ? "failure" : "error";
        const char* type = result.outcome == CaseOutcome::Failed ? "ImageMismatch" : "MissingGolden";
        xml << ">\n      <" << element << " message=\"" << escaped(message) << "\" type=\"" << type << "\">"
            << escaped(result.scene.string() + ": " + figures(result)) << "</" << element << ">\n    </testcase>\n";
    }
    xml << "  </testsuite>\n</testsuites>\n";
    return xml.str();
}

std::string htmlPage(const std::string& suiteName, const std::vector<CaseResult>& results) {
    std::ostringstream html;
    html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>tstyles check: " << escaped(suiteName)
         << "</title>\n<style>body{font-family:sans-serif;background:#222;color:#ddd}td,th{padding:4px 8px}"
            ".FAIL,.NO{color:#f66}.pass,.updated{color:#6c6}img{max-width:32vw;image-rendering:pixelated;"
            "background:repeating-conic-gradient(#555 0 25%,#777 0 50%) 50%/16px 16px}</style></head><body>\n"
         << "<h1>tstyles check: " << escaped(suiteName) << "</h1>\n<table>\n<tr><th>case</th><th>result</th><th>figures</th></tr>\n";
    for (const CaseResult& result : results) {
        const std::string outcome = toString(result.outcome);
        html << "<tr><td><a href=\"#" << escaped(result.name) << "\">" << escaped(result.name) << "</a></td><td class=\""
             << outcome.substr(0, outcome.find(' ')) << "\">" << outcome << "</td><td>" << escaped(figures(result))
             << "</td></tr>\n";
    }
    html << "</table>\n";
    for (const CaseResult& result : results) {
        if (passed(result)) continue;
        html << "<h2 id=\"" << escaped(result.name) << "\">" << escaped(result.name) << "</h2>\n<p>";
        for (const std::string& problem : result.problems) html << escaped(problem) << "<br>";
        html << "</p>\n<table><tr><th>expected</th><th>actual</th><th>difference</th></tr><tr>";
        // A case without a golden has only its render to show.
        const bool compared = result.expected && result.difference;
        for (const char* kind : {"expected", "actual", "diff"}) {
            if (!compared && std::string(kind) != "actual") {
                html << "<td>(none)</td>";
                continue;
            }
            html << "<td><img src=\"" << escaped(result.name) << "." << kind << ".png\" alt=\"" << kind << "\"></td>";
        }
        html << "</tr></table>\n";
    }
    html << "</body></html>\n";
    return html.str();
}

void writeText(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throwInputError(file, "", "cannot write the report file");
}

}  // namespace

std::string toString(CaseOutcome outcome) {
    switch (outcome) {
        case CaseOutcome::Passed: return "pass";
        case CaseOutcome::Failed: return "FAIL";
        case CaseOutcome::MissingGolden: return "NO GOLDEN";
        case CaseOutcome::Updated: return "updated";
    }
    return "?";
}

void requireReplaceableReportFolder(const fs::path& folder) {
    const PathSource source{"", "--report"};
    const PathKind kind = userPathKind(source, folder);
    if (kind == PathKind::Missing) return;  // made, with its parents, when the report is written
    if (kind != PathKind::Folder) throwInputError(folder, "--report", "is a file, not a report folder");
    const fs::directory_iterator entries = withUserPath(source, folder, [&] { return fs::directory_iterator(folder); });
    for (const fs::directory_entry& entry : entries) {
        const std::string name = entry.path().filename().string();
        if (name != "index.html" && name != "junit.xml" && entry.path().extension() != ".png")
            throwInputError(folder, "", "holds " + name + ", which no report wrote; give a new or empty folder");
    }
}

void writeCheckReport(const fs::path& target, const std::string& suiteName, const std::vector<CaseResult>& results) {
    const fs::path folder = userAbsolutePath(PathSource{"", "--report"}, target);
    const fs::path partial =
        folder.parent_path() / ("." + folder.filename().string() + ".partial-" + std::to_string(getpid()));
    std::error_code error;
    fs::remove_all(partial, error);
    fs::create_directories(partial, error);
    if (error) throwInputError(folder, "", "cannot make the report folder: " + error.message());
    try {
        for (const CaseResult& result : results) {
            if (passed(result)) continue;
            if (result.expected && result.difference)
                writeImage(*result.expected, partial / (result.name + ".expected.png"));
            if (result.actual) writeImage(*result.actual, partial / (result.name + ".actual.png"));
            if (result.expected && result.actual && result.difference)
                writeImage(differenceHeatMap(*result.actual, *result.expected, std::max(8, result.difference->maxDelta)),
                           partial / (result.name + ".diff.png"));
        }
        writeText(partial / "index.html", htmlPage(suiteName, results));
        writeText(partial / "junit.xml", junitXml(suiteName, results));
        withUserPath(PathSource{"", "--report"}, folder, [&] {
            fs::remove_all(folder);
            fs::rename(partial, folder);
        });
    } catch (...) {
        fs::remove_all(partial, error);
        throw;
    }
}

}  // namespace tstyles::cli
