// odd_profile.json, .geojson and .csv written a batch at a time
// (ProfileFiles) are byte for byte those of the whole profile in one batch,
// and odd_profile.json that of write_json, on random profiles cut into
// random batches, empty ones included; the scratch file goes at the end.
#include "railodd/odd/profile_files.hpp"
#include "railodd/odd/profile_summary.hpp"
#include "railodd/util/errors.hpp"
#include "odd_profile_support.hpp"
#include "test_support.hpp"

#include <random>
#include <sstream>

using namespace railodd;
using namespace railodd::test;

namespace {

odd::TaggedElement random_element(std::mt19937& rng, std::size_t track, double& chainage) {
    static const std::vector<std::pair<std::string, std::string>> kinds{
        {"Scenery/Track geometry/Horizontal/Curve", "sc.geo.hz.curve"},
        {"Scenery/Crossings/Level crossing", "sc.xing.level"},
        {"Scenery/Stations and stops/Station", "sc.stn.station"},
        {"Operational Conditions/Speed/Speed limit", "op.speed.limit"},
        {"Odd \"kind\", with <quotes>\n", "x.odd"}};
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const auto& [path, id] = kinds[rng() % kinds.size()];
    const double s0 = chainage, s1 = u(rng) < 0.3 ? s0 : s0 + 1000.0 * u(rng);
    chainage = s1 + 10.0 * u(rng);
    std::vector<odd::TaggedAttribute> attrs;
    if (u(rng) < 0.7) {
        attrs.push_back({"radius", 100.0 + 5000.0 * u(rng)});
    }
    if (u(rng) < 0.5) {
        attrs.push_back({"name", std::string{"a, \"b\"; c=d"}});
    }
    if (u(rng) < 0.3) {
        attrs.push_back({"lights", u(rng) < 0.5});
    }
    odd::TaggedElement e = tagged(path, id, attrs, std::to_string(rng() % 9), s0 - chainage / 2, s1 - chainage / 2,
                                  s0, s1, {"way:" + std::to_string(rng() % 50)});
    e.track = track;
    e.reversed = u(rng) < 0.2;
    if (u(rng) < 0.1) {
        e.lonlat.clear();
    }
    return e;
}

odd::OddProfile random_profile(std::mt19937& rng) {
    odd::OddProfile p = sample_profile();
    p.elements.clear();
    const std::size_t tracks = rng() % 6;
    p.tracks = tracks;
    for (std::size_t t = 0; t < tracks; ++t) {
        double chainage = 0.0;
        const std::size_t n = rng() % 40;
        for (std::size_t i = 0; i < n; ++i) {
            p.elements.push_back(random_element(rng, t, chainage));
        }
        p.track_ends.push_back({t, 100 + static_cast<std::int64_t>(t), 200, 0.5, -1.25});
    }
    if (rng() % 2) {
        p.unparsed.clear();
    }
    p.summary = odd::summarize(p, nullptr);
    return p;
}

struct Files {
    std::string json, geojson, csv;
};

Files streamed(const odd::OddProfile& p, std::mt19937& rng, const fs::path& scratch) {
    std::ostringstream json, geojson, csv;
    {
        odd::ProfileFiles files(json, geojson, csv, scratch);
        odd::OddProfile head = p;
        head.elements.clear();
        files.begin(head);
        for (std::size_t i = 0; i < p.elements.size() || rng() % 3 == 0;) {
            const std::size_t n = std::min(p.elements.size() - i, static_cast<std::size_t>(rng() % 12));
            std::deque<odd::TaggedElement> batch(p.elements.begin() + static_cast<std::ptrdiff_t>(i),
                                                 p.elements.begin() + static_cast<std::ptrdiff_t>(i + n));
            files.add(batch); // empty batches too
            i += n;
            if (i >= p.elements.size() && rng() % 2) {
                break;
            }
        }
        files.end(head);
    }
    return {json.str(), geojson.str(), csv.str()};
}

} // namespace

TEST(OddProfileFiles, BatchesGiveTheWholeProfilesFilesByteForByte) {
    std::mt19937 rng(20261126);
    const fs::path dir = scratch_dir();
    std::size_t empty = 0, elements = 0;
    for (int round = 0; round < 200; ++round) {
        const odd::OddProfile p = random_profile(rng);
        empty += p.elements.empty() ? 1 : 0;
        elements += p.elements.size();
        const fs::path scratch = dir / "rows.tmp";
        const Files f = streamed(p, rng, scratch);
        std::ostringstream json;
        odd::write_json(p, json);
        const ProfileTexts whole = profile_files_of(p);
        ASSERT_EQ(f.json, json.str()) << "round " << round;
        ASSERT_EQ(f.json, whole.json) << "round " << round;
        ASSERT_EQ(f.geojson, whole.geojson) << "round " << round;
        ASSERT_EQ(f.csv, whole.csv) << "round " << round;
        EXPECT_FALSE(fs::exists(scratch)) << "round " << round;
        // And it reads back as the profile written.
        EXPECT_EQ(odd::to_json_text(odd::profile_from_json(nlohmann::ordered_json::parse(f.json))), f.json);
    }
    EXPECT_GT(empty, 5u);
    EXPECT_GT(elements, 5000u);
}

TEST(OddProfileFiles, AnUnwritableScratchFileIsAnOutputError) {
    std::ostringstream json, geojson, csv;
    const fs::path scratch = scratch_dir() / "missing" / "rows.tmp";
    EXPECT_THROW(odd::ProfileFiles files(json, geojson, csv, scratch), railodd::OutputError);
}
