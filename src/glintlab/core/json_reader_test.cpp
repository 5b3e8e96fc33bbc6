#include "glintlab/core/json_reader.h"

#include <gtest/gtest.h>

#include <sstream>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

std::string parse_error(const std::string& text) {
    std::istringstream in(text);
    try {
        parse_json(in, "f.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(JsonReader, DuplicateKeyNamesFilePathAndKey) {
    const std::string e =
        parse_error(R"({"materials": [{"name": "a"}, {"name": "b", "type": "x", "name": "c"}]})");
    EXPECT_NE(e.find("f.json: /materials/1/name: duplicate key \"name\""), std::string::npos) << e;
    const std::string top = parse_error(R"({"film": {}, "camera": {}, "film": {}})");
    EXPECT_NE(top.find("f.json: /film: duplicate key \"film\""), std::string::npos) << top;
    // The same key in different objects is fine.
    EXPECT_EQ(parse_error(R"({"a": {"x": 1}, "b": {"x": [1, {"x": 2}]}})"), "");
}

TEST(JsonReader, NumberBeyondDoubleNamesFileAndPath) {
    const std::string e = parse_error(R"({"film": {"width": 8, "exposure": 1e400}})");
    EXPECT_NE(e.find("f.json: /film/exposure: number out of range"), std::string::npos) << e;
    const std::string in_array = parse_error(R"({"a": [1, 2, -1e999]})");
    EXPECT_NE(in_array.find("f.json: /a/2: number out of range"), std::string::npos) << in_array;
    const std::string syntax = parse_error(R"({"a": })");
    EXPECT_NE(syntax.find("f.json: invalid JSON"), std::string::npos) << syntax;
}

// Nesting 100 000 deep used to overflow the stack when an error message
// dumped the value; it is refused while parsing, naming the path, at one
// level past kMaxJsonNesting, and accepted at that depth.
TEST(JsonReader, DeepNestingIsAnErrorNotACrash) {
    const auto nested = [](size_t depth) {
        return R"({"film": {"width": )" + std::string(depth, '[') + std::string(depth, ']') + "}}";
    };
    const std::string e = parse_error(nested(100000));
    EXPECT_NE(e.find("f.json: /film/width/0/0/0"), std::string::npos) << e.substr(0, 200);
    EXPECT_NE(e.find("nested deeper than 256 levels"), std::string::npos) << e.substr(0, 200);
    EXPECT_EQ(parse_error(nested(kMaxJsonNesting - 2)), "");  // the root and "film" are 2 levels
    EXPECT_NE(parse_error(nested(kMaxJsonNesting - 1)), "");
    EXPECT_EQ(json_nesting_depth(nested(100000)), 100002u);
    EXPECT_EQ(json_nesting_depth(R"({"a": "[[[{{{\"[", "b": [[1]]})"), 3u);
}

// A megabyte-long unknown or duplicate key is cut in the message, not echoed.
TEST(JsonReader, LongKeysAreCutInMessages) {
    const std::string key(1 << 20, 'k');
    const std::string dup = parse_error("{\"" + key + "\": 1, \"" + key + "\": 2}");
    EXPECT_NE(dup.find("duplicate key"), std::string::npos);
    EXPECT_LT(dup.size(), 400u);
    const nlohmann::json j = {{key, 1}, {"known", 2}};
    JsonObject o(j, "/m", "f.json");
    o.number("known", 0.0, 0.0, 10.0);
    try {
        o.finish();
        ADD_FAILURE() << "unknown key accepted";
    } catch (const Error& err) {
        const std::string m = err.what();
        EXPECT_LT(m.size(), 400u);
        EXPECT_NE(m.find("(1048576 bytes)"), std::string::npos) << m;
        EXPECT_NE(m.find("known keys here: known"), std::string::npos) << m;
    }
}

std::string number_error(double x, const NumberRange& r) {
    const nlohmann::json j = {{"v", x}};
    JsonObject o(j, "/m", "f.json");
    try {
        o.number("v", 0.0, r);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(JsonReader, ClosedBoundsAreAcceptedAsWritten) {
    // 0.001 is the documented minimum; as a float bound it was 0.0010000000475
    // and rejected 0.001 itself.
    const NumberRange r{0.001, 1.0};
    EXPECT_EQ(number_error(0.001, r), "");
    EXPECT_EQ(number_error(1.0, r), "");
    const std::string e = number_error(0.000999, r);
    EXPECT_NE(e.find("f.json: /m/v: value 0.000999 out of range: allowed in [0.001, 1]"),
              std::string::npos)
        << e;
    const nlohmann::json j = {{"roughness", {0.001, 1.0}}, {"c", 0.02}};
    JsonObject o(j, "", "f.json");
    EXPECT_EQ(o.vec2("roughness", glm::vec2(0.5f), 1e-3, 1.0), glm::vec2(0.001f, 1.0f));
    EXPECT_EQ(o.color("c", glm::vec3(0.5f), 0.02, 1.0), glm::vec3(0.02f));
}

TEST(JsonReader, OpenEndExcludesOnlyItsBound) {
    const NumberRange eta{1.0, 4.0, true, false, true};  // (1, 4], stored as float
    EXPECT_EQ(eta.text(), "(1, 4]");
    const std::string at_end = number_error(1.0, eta);
    EXPECT_NE(at_end.find("value 1 out of range: allowed in (1, 4]"), std::string::npos) << at_end;
    // The next float above 1 is inside; the doubles between 1 and it round
    // onto the excluded end in float and say so.
    EXPECT_EQ(number_error(1.0 + 1.2e-7, eta), "");
    EXPECT_EQ(number_error(1.0001, eta), "");
    const std::string rounds = number_error(1.0 + 1e-9, eta);
    EXPECT_NE(rounds.find("allowed in (1, 4] (it is stored as a float and rounds to 1)"),
              std::string::npos)
        << rounds;
    EXPECT_EQ(number_error(4.0, eta), "");
    EXPECT_NE(number_error(4.0000001, eta).find("(1, 4]"), std::string::npos);
    EXPECT_EQ((NumberRange{0.0, 1.0, false, true}.text()), "[0, 1)");
    EXPECT_EQ((NumberRange{0.0, INFINITY, true}.text()), "> 0");
}

}  // namespace
}  // namespace glintlab
