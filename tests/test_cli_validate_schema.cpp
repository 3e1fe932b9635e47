// `railodd validate --xsd-dir` against the ASAM schemas in ../shared/data/schemas
// (xmllint for 1.7, python3-xmlschema for 1.8).
#include "test_support.hpp"
#include "xodr_check_support.hpp"

using namespace railodd::test;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

fs::path schemas() { return shared_data().empty() ? fs::path{} : shared_data() / "schemas"; }

std::string doc(int rev_minor, const std::string& lane_type) {
    const auto recs = rail_alignment({0.0, 0.0, 0.0, 0.0});
    return document(road_xml({"1", total_length(recs), geometries_xml(recs), lane_type}), rev_minor);
}

} // namespace

TEST(CliValidateSchema, OpenDrive17AgainstXmllint) {
    const fs::path xsd = schemas() / "OpenDRIVE_1.7" / "localSchema";
    if (schemas().empty() || !fs::is_directory(xsd)) {
        GTEST_SKIP() << "../shared/data/schemas/OpenDRIVE_1.7/localSchema is absent: skipping schema test";
    }
    if (run_command("command -v xmllint").exit_code != 0) {
        GTEST_SKIP() << "xmllint is not installed (libxml2-utils): skipping schema test";
    }
    const auto dir = scratch_dir();
    const auto good = run_railodd("validate " + quoted(write_file(dir / "good.xodr", doc(7, "rail"))) +
                                  " --xsd-dir " + quoted(xsd));
    EXPECT_EQ(good.exit_code, 0) << good.output;
    EXPECT_NE(good.output.find("schema: valid against"), std::string::npos) << good.output;
    EXPECT_NE(good.output.find("opendrive_17_core.xsd"), std::string::npos) << good.output;

    const auto bad = run_railodd("validate " + quoted(write_file(dir / "bad.xodr", doc(7, "monorail"))) +
                                 " --xsd-dir " + quoted(xsd));
    EXPECT_EQ(bad.exit_code, 5) << bad.output;
    EXPECT_NE(bad.output.find("schema: INVALID"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("monorail"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("checks: 0 error(s)"), std::string::npos) << bad.output;
}

TEST(CliValidateSchema, OpenDrive18AgainstXmlschemaFromTheSchemasFolder) {
    if (schemas().empty() || !fs::is_directory(schemas() / "OpenDRIVE_1.8")) {
        GTEST_SKIP() << "../shared/data/schemas/OpenDRIVE_1.8 is absent: skipping schema test";
    }
    if (run_command("/usr/bin/python3 -c 'import xmlschema'").exit_code != 0) {
        GTEST_SKIP() << "python3-xmlschema is not installed: skipping 1.8 schema test";
    }
    const auto dir = scratch_dir();
    // The schemas folder itself: the core schema is found below it by name.
    const auto good = run_railodd("validate " + quoted(write_file(dir / "good.xodr", doc(8, "rail"))) +
                                  " --xsd-dir " + quoted(schemas()));
    EXPECT_EQ(good.exit_code, 0) << good.output;
    EXPECT_NE(good.output.find("OpenDRIVE_Core.xsd"), std::string::npos) << good.output;
    const auto bad = run_railodd("validate " + quoted(write_file(dir / "bad.xodr", doc(8, "monorail"))) +
                                 " --xsd-dir " + quoted(schemas()));
    EXPECT_EQ(bad.exit_code, 5) << bad.output;
    EXPECT_NE(bad.output.find("schema: INVALID"), std::string::npos) << bad.output;
}
