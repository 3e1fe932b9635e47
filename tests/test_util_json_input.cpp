// The shared reader of JSON railodd reads back: nesting beyond any file
// railodd writes is refused before parsing (a deep tree overflows the stack
// when copied or dumped), and fields of the wrong type are bad input naming
// the file, the JSON path and the value.
#include "railodd/util/errors.hpp"
#include "railodd/util/json_depth.hpp"
#include "railodd/util/json_input.hpp"
#include "railodd/util/json_shape.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <functional>

using namespace railodd;
using railodd::test::scratch_dir;
using railodd::test::write_file;

namespace {

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

} // namespace

TEST(JsonInput, DepthCountsArraysAndObjectsButNotStrings) {
    EXPECT_EQ(json_depth(R"({"a": [1, {"b": "[[[[{{{{"}]})"), 3);
    EXPECT_EQ(json_depth(R"(["\"[[[", "\\", []])"), 2);
    EXPECT_EQ(json_depth("12"), 0);
}

TEST(JsonInput, AMillionBracketsAreRefusedBeforeParsing) {
    const auto file = write_file(scratch_dir() / "deep.json", std::string(1000000, '['));
    const std::string m = message_of([&] { read_json_file(file, "scenario manifest"); });
    EXPECT_NE(m.find(file.string()), std::string::npos) << m;
    EXPECT_NE(m.find("nested deeper than"), std::string::npos) << m;
}

TEST(JsonInput, NestingAsDeepAsTheLimitIsRead) {
    const int n = max_json_depth;
    const auto file = write_file(scratch_dir() / "ok.json", std::string(n, '[') + std::string(n, ']'));
    EXPECT_TRUE(read_json_file(file, "test").is_array());
}

TEST(JsonInput, AWrongTypeNamesFilePathAndValue) {
    const auto j = nlohmann::ordered_json::parse(R"({"scenarios": [{"id": "a", "anchor": {"s": "12"}}]})");
    const std::vector<JsonField> shape = {{"scenarios", JsonKind::array},
                                          {"scenarios/*", JsonKind::object},
                                          {"scenarios/*/id", JsonKind::string},
                                          {"scenarios/*/anchor", JsonKind::object},
                                          {"scenarios/*/anchor/s", JsonKind::number}};
    const std::string m = message_of([&] { require_shape(j, shape, "m.json"); });
    EXPECT_EQ(m, "m.json: /scenarios/0/anchor/s: expected a number, found string \"12\"");
}

TEST(JsonInput, AMissingRequiredFieldIsNamedAndOptionalNullsPass) {
    const auto j = nlohmann::ordered_json::parse(R"({"ego": {"end": null}, "actors": [{}]})");
    EXPECT_NO_THROW(require_shape(j, {{"ego/end", JsonKind::object, false}, {"ego/end/s", JsonKind::number}}, "m.json"));
    const std::string m = message_of([&] { require_shape(j, {{"actors/*/name", JsonKind::string}}, "m.json"); });
    EXPECT_EQ(m, "m.json: /actors/0/name: expected a string, found nothing (missing)");
}
