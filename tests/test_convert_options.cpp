// The convert options' one table (railodd/convert/options.hpp): the command
// line's flags and the batch routes file's keys are both made from it, so
// every option reaches Options the same way from both, and both refuse the
// same bad values.
#include "batch_routes.hpp"
#include "option_table.hpp"
#include "test_support.hpp"

#include "railodd/convert/options.hpp"
#include "railodd/util/errors.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

using namespace railodd;
using convert::OptionKind;
using convert::OptionSpec;
namespace fs = std::filesystem;

namespace {

// A value of the row that is not its default.
std::vector<std::string> sample(const OptionSpec& s) {
    const std::string key{s.key};
    switch (s.kind) {
    case OptionKind::path: return {"/tmp/railodd-options/" + key + ".file"};
    case OptionKind::paths: return {"/tmp/railodd-options/" + key + "-1.tif", "/tmp/railodd-options/" + key + "-2.tif"};
    case OptionKind::number: return {std::to_string(0.25 * s.lo + 0.75 * s.hi)};
    case OptionKind::count: return {"3"};
    case OptionKind::integer: return {"4242"};
    case OptionKind::bbox: return {"10.5,47.1,10.6,47.2"};
    case OptionKind::flag: return {};
    case OptionKind::text:
        if (!s.choices.empty()) {
            return {std::string{s.choices.back()}};
        }
        return {s.pattern.empty() ? "Station " + key : "2024-01-02T03:04:05Z"};
    }
    return {};
}

// A value the row's check refuses; empty where every value is one.
std::string bad(const OptionSpec& s) {
    switch (s.kind) {
    case OptionKind::number: return std::to_string(s.hi + 1.0);
    case OptionKind::integer: return "12x";
    case OptionKind::bbox: return "10.6,47.1,10.5,47.2,1";
    case OptionKind::text: return s.choices.empty() && s.pattern.empty() ? "" : "2024-13";
    default: return "";
    }
}

convert::Options parse(std::vector<std::string> args) {
    CLI::App app{"test"};
    convert::Options o;
    cli::add_table_options(app, o);
    std::vector<std::string> reversed(args.rbegin(), args.rend()); // CLI11 parses a reversed vector
    app.parse(reversed);
    return o;
}

std::vector<std::string> with_flag(const OptionSpec& s, std::vector<std::string> args) {
    for (const std::string& v : sample(s)) {
        args.insert(args.end(), {convert::flag_of(s), v});
    }
    if (s.kind == OptionKind::flag) {
        args.push_back(convert::flag_of(s));
    }
    return args;
}

std::string yaml_value(const OptionSpec& s) {
    const std::vector<std::string> v = sample(s);
    if (s.kind == OptionKind::flag) {
        return "true";
    }
    if (s.kind == OptionKind::paths) {
        return "[" + v[0] + ", " + v[1] + "]";
    }
    return "\"" + v[0] + "\"";
}

// The route's convert argv as the batch gives it to `railodd convert`. The
// routes file goes into this test's own folder: ctest runs the tests of this
// file side by side.
std::vector<std::string> batch_args(const std::string& key, const std::string& value) {
    static const fs::path dir = test::scratch_dir();
    const fs::path file = dir / "routes.yaml";
    std::ofstream(file) << "routes:\n  - id: r\n    input: /tmp/in.osm\n    " << key << ": " << value << "\n";
    const cli::BatchFile b = cli::load_batch_file(file);
    std::vector<std::string> a = cli::convert_args(b.routes.at(0), "/tmp/out", false);
    a.erase(a.begin()); // "convert"
    return a;
}

const std::vector<std::string> required{"/tmp/in.osm", "-o", "/tmp/out"};
// What the batch gives every route: --no-timings, report.json byte-identical whatever the load.
const std::vector<std::string> base{"/tmp/in.osm", "-o", "/tmp/out", "--no-timings"};

} // namespace

TEST(ConvertOptions, EveryRowHasItsOwnFieldAndKey) {
    std::set<std::string_view> keys;
    std::vector<convert::OptionField> fields;
    for (const OptionSpec& s : convert::option_table()) {
        EXPECT_TRUE(keys.insert(s.key).second) << s.key;
        EXPECT_EQ(convert::find_option(s.key), &s);
        for (const convert::OptionField& f : fields) {
            EXPECT_FALSE(f == s.field) << s.key << " is bound to another row's field";
        }
        fields.push_back(s.field);
        EXPECT_FALSE(s.help.empty()) << s.key;
    }
    EXPECT_EQ(convert::find_option("no_such_option"), nullptr);
}

TEST(ConvertOptions, TheCommandLineSetsEveryOption) {
    const convert::Options defaults = parse(required);
    for (const OptionSpec& s : convert::option_table()) {
        if (s.positional || s.required) {
            continue;
        }
        const convert::Options o = parse(with_flag(s, required));
        EXPECT_NE(o, defaults) << convert::flag_of(s) << " changed nothing";
    }
}

TEST(ConvertOptions, BatchAndCommandLineAgreeOnEveryRouteOption) {
    for (const OptionSpec& s : convert::option_table()) {
        if (!s.per_route) {
            continue;
        }
        const convert::Options direct = parse(with_flag(s, base));
        const convert::Options batch = parse(batch_args(std::string{s.key}, yaml_value(s)));
        EXPECT_EQ(batch, direct) << s.key;
        EXPECT_NE(batch, parse(base)) << s.key << " changed nothing";
    }
}

TEST(ConvertOptions, OnlyTheBatchsOwnOptionsAreNotPerRoute) {
    std::set<std::string_view> own;
    for (const OptionSpec& s : convert::option_table()) {
        if (!s.per_route) {
            own.insert(s.key);
        }
    }
    EXPECT_EQ(own, (std::set<std::string_view>{"input", "output", "threads", "no_timings"}));
}

TEST(ConvertOptions, BothRefuseTheSameBadValues) {
    int checked = 0;
    for (const OptionSpec& s : convert::option_table()) {
        const std::string v = bad(s);
        if (v.empty() || !s.per_route) {
            continue;
        }
        ++checked;
        std::vector<std::string> args = base;
        args.insert(args.end(), {convert::flag_of(s), v});
        EXPECT_THROW(parse(args), CLI::ValidationError) << s.key << " " << v;
        EXPECT_FALSE(convert::check_value(s, v).empty()) << s.key;
        try {
            batch_args(std::string{s.key}, "\"" + v + "\"");
            ADD_FAILURE() << s.key << ": the routes file took " << v;
        } catch (const InputError& e) {
            EXPECT_NE(std::string{e.what()}.find(std::string{s.key}), std::string::npos) << e.what();
        }
    }
    EXPECT_GE(checked, 8); // node_noise, fit_method, the distances, relation, bbox, odr_version, date
}

TEST(ConvertOptions, ChecksSayWhatIsWrong) {
    const OptionSpec& noise = *convert::find_option("node_noise");
    EXPECT_EQ(convert::check_value(noise, "9"), "'9' is outside [0.01, 5]");
    EXPECT_EQ(convert::check_value(noise, "nan"), "'nan' is not a finite number");
    EXPECT_EQ(convert::check_value(*convert::find_option("fit_method"), "spline"), "'spline' is not one of design, windowed");
    EXPECT_EQ(convert::check_value(*convert::find_option("date"), "2024"), "'2024' is not YYYY-MM-DDTHH:MM:SS[Z]");
    EXPECT_EQ(convert::check_value(*convert::find_option("threads"), "-1"), "'-1' is not a non-negative integer");
    EXPECT_EQ(convert::check_value(*convert::find_option("polygon"), ""), "the path is empty");
    EXPECT_TRUE(convert::check_value(*convert::find_option("bbox"), "10.5,47.1,10.6,47.2").empty());
}
