// JSON parsed in one place (core/json_text.h) and read by one typed reader (core/json_field.h):
// the messages name the file, the field and the problem.
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "tstyles/core/errors.h"
#include "tstyles/core/json_field.h"
#include "tstyles/core/json_text.h"

namespace tstyles {
namespace {

std::string parseError(const std::string& text, JsonComments comments) {
    try {
        parseJsonText(text, "suite.json", comments);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(JsonText, ABadDocumentNamesTheFileAndTheLine) {
    const std::string trailingComma = parseError("{\n  \"a\": 1,\n}", JsonComments::Allowed);
    EXPECT_EQ(trailingComma.rfind("suite.json: not valid JSON: parse error at line 3", 0), 0u) << trailingComma;
    const std::string huge = parseError("{\"a\": 1e999}", JsonComments::Refused);
    EXPECT_EQ(huge.rfind("suite.json: not valid JSON: a number is too large for a double (", 0), 0u) << huge;
    EXPECT_NE(huge.find("1e999"), std::string::npos) << huge;
}

// Issue 54: 25 000 nested arrays took more than 8 GiB of address space. The depth is refused as it
// is met; 100 levels (a scene needs 6) still read.
TEST(JsonText, NestingBeyondAHundredLevelsIsRefused) {
    auto nested = [](int depth) { return std::string(depth, '[') + std::string(depth, ']'); };
    EXPECT_NO_THROW(parseJsonText(nested(100), "scene.json", JsonComments::Allowed));
    EXPECT_EQ(parseError(nested(101), JsonComments::Allowed),
              "suite.json: arrays and objects nested more than 100 deep; no document read here needs so many");
    const std::string deep = "{\"stf\": " + nested(25000) + "}";
    EXPECT_NE(parseError(deep, JsonComments::Allowed).find("nested more than 100 deep"), std::string::npos);
}

TEST(JsonText, CommentsAreReadOnlyWhereAllowed) {
    const std::string commented = "// a hand-written file\n{\"a\": /* one */ 1}";
    EXPECT_EQ(parseJsonText(commented, "scene.json", JsonComments::Allowed)["a"], 1);
    EXPECT_NE(parseError(commented, JsonComments::Refused).find("not valid JSON"), std::string::npos);
    EXPECT_TRUE(probeJsonText(commented, JsonComments::Refused).is_discarded());
    EXPECT_FALSE(probeJsonText(commented, JsonComments::Allowed).is_discarded());
}

TEST(JsonText, AKeyGivenTwiceInOneObjectIsRefusedByItsPath) {
    const std::string twice = "given twice; a key may appear once in an object";
    EXPECT_EQ(parseError(R"({"a": 1, "a": 2})", JsonComments::Refused), "suite.json: a: " + twice);
    EXPECT_EQ(parseError(R"({"compositor": {"name": "x", "direction": "falling", "direction": "rising"}})",
                         JsonComments::Refused),
              "suite.json: compositor.direction: " + twice);
    EXPECT_EQ(parseError(R"({"stf": {"opacity": [{"at": 0}, [1, {"b": 2}], {"at": 0, "at": 1}]}})",
                         JsonComments::Refused),
              "suite.json: stf.opacity[2].at: " + twice);
    // One key in several objects is one in each.
    const nlohmann::json document = parseJsonText(R"({"a": {"at": 1}, "b": [{"at": 2}, {"at": 3}], "at": 4})", "",
                                                  JsonComments::Refused);
    EXPECT_EQ(document["b"][1]["at"], 3);
}

TEST(JsonField, AMissingKeyFailsWithWhatTheCallerSays) {
    const nlohmann::json document = nlohmann::json::parse(R"({"cases": [{"name": "a"}]})");
    const std::filesystem::path file = "suite.json";
    const JsonField root(file, document, "");
    const JsonField entry = root.member("cases").element(0);
    try {
        entry.member("scene", "missing; every case names its scene file");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(), "suite.json: cases[0].scene: missing; every case names its scene file");
    }
    try {
        entry.allowOnlyKeys({"scene"});
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_STREQ(error.what(),
                     "suite.json: cases[0].name: unknown key; the keys allowed in \"cases[0]\" are: scene");
    }
}

}  // namespace
}  // namespace tstyles
