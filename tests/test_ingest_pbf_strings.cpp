// OSM PBF string tables with NUL bytes and arbitrary bytes: the reader refuses
// a NUL in any key, value or role an object uses, naming the object, and never
// crashes whatever bytes the table holds.
#include "osm_scan.hpp"
#include "pbf_strings.hpp"
#include "pbf_test_support.hpp"
#include "railodd/ingest/osm_reader.hpp"
#include "railodd/util/errors.hpp"
#include "test_support.hpp"

#include <osmium/builder/osm_object_builder.hpp>
#include <osmium/memory/buffer.hpp>

#include <random>

using namespace railodd::ingest;
using railodd::InputError;
using railodd::test::PbfBuilder;
using railodd::test::scratch_dir;

namespace {

using namespace std::string_literals;

// A 300 m rail track w10 over n1..n3 with a signal on n2 and a route relation.
PbfBuilder route() {
    PbfBuilder b;
    b.nodes = {{1, 10.000, 48.0, {}}, {2, 10.002, 48.0, {{"railway", "signal"}}}, {3, 10.004, 48.0, {}}};
    b.ways = {{10, {{"railway", "rail"}, {"maxspeed", "120"}}, {1, 2, 3}}};
    b.relations = {{100, {{"type", "route"}, {"route", "train"}}, {{1, 10, ""}}}};
    return b;
}

std::string read_error(const PbfBuilder& b, const std::string& name = "input.osm.pbf") {
    const auto file = scratch_dir() / name;
    PbfBuilder copy = b;
    copy.write(file);
    try {
        read_osm(file, {});
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

} // namespace

TEST(IngestPbfStrings, WellFormedFileReads) {
    for (const bool zlib : {true, false}) {
        PbfBuilder b = route();
        b.zlib = zlib;
        const auto file = scratch_dir() / "ok.osm.pbf";
        b.write(file);
        const IngestResult r = read_osm(file, {});
        ASSERT_EQ(r.tracks.size(), 1U);
        EXPECT_EQ(r.tracks[0].id, 10);
        EXPECT_EQ(r.tracks[0].tags.at("maxspeed"), "120");
    }
}

TEST(IngestPbfStrings, NulInWayKeyNamesTheWay) {
    for (const bool zlib : {true, false}) {
        PbfBuilder b = route();
        b.zlib = zlib;
        b.ways[0].tags.emplace_back("na\0me"s, "x");
        const std::string e = read_error(b);
        EXPECT_NE(e.find("input.osm.pbf"), std::string::npos) << e;
        EXPECT_NE(e.find("OSM way 10: tag key holds a NUL byte"), std::string::npos) << e;
    }
}

TEST(IngestPbfStrings, NulInNodeValueNamesTheNode) {
    PbfBuilder b = route();
    b.nodes[2].tags.emplace_back("name", "a\0b\0c"s); // an even number of NULs: no parity would tell
    const std::string e = read_error(b);
    EXPECT_NE(e.find("OSM node 3: tag value holds a NUL byte"), std::string::npos) << e;
}

TEST(IngestPbfStrings, NulInMemberRoleNamesTheRelation) {
    PbfBuilder b = route();
    b.relations[0].members[0].role = "sto\0p"s;
    const std::string e = read_error(b);
    EXPECT_NE(e.find("OSM relation 100: member role holds a NUL byte"), std::string::npos) << e;
}

TEST(IngestPbfStrings, StringTableAfterTheGroupsIsCheckedToo) {
    PbfBuilder b = route();
    b.string_table_last = true;
    b.ways[0].tags.emplace_back("k", "\0"s);
    const std::string e = read_error(b);
    EXPECT_NE(e.find("OSM way 10: tag value holds a NUL byte"), std::string::npos) << e;
}

TEST(IngestPbfStrings, UnusedNulStringIsHarmless) {
    PbfBuilder b = route();
    b.unused_strings = {"x\0y"s};
    EXPECT_EQ(read_error(b), "");
}

// Random byte strings, NULs included, in keys, values and roles: every file
// either reads or is refused with an InputError that names an object; one
// with a NUL anywhere an object uses is always refused.
TEST(IngestPbfStrings, RandomBytesNeverCrash) {
    std::mt19937_64 rng(20261124);
    auto bytes = [&rng](std::size_t max_len) {
        std::string s(rng() % (max_len + 1), '\0');
        for (auto& c : s) {
            const auto r = rng() % 8;
            c = r == 0 ? '\0' : static_cast<char>(r < 4 ? 'a' + rng() % 26 : rng() % 256);
        }
        return s;
    };
    int refused = 0;
    for (int round = 0; round < 200; ++round) {
        PbfBuilder b = route();
        b.zlib = round % 2 == 0;
        bool has_nul = false;
        for (int t = 0; t < 3; ++t) {
            auto& tags = rng() % 3 == 0 ? b.nodes[rng() % 3].tags : b.ways[0].tags;
            tags.emplace_back(bytes(6), bytes(6));
            has_nul = has_nul || tags.back().first.find('\0') != std::string::npos ||
                      tags.back().second.find('\0') != std::string::npos;
        }
        b.relations[0].members[0].role = bytes(4);
        has_nul = has_nul || b.relations[0].members[0].role.find('\0') != std::string::npos;
        const std::string e = read_error(b, "random.osm.pbf");
        if (has_nul) {
            EXPECT_NE(e.find("holds a NUL byte"), std::string::npos) << "round " << round << ": " << e;
        }
        if (!e.empty()) {
            EXPECT_NE(e.find("random.osm.pbf"), std::string::npos) << e;
            ++refused;
        }
    }
    EXPECT_GT(refused, 0);
}

// The guard every pass runs on each object: a tag list whose strings do not
// pair up within its bounds is refused before libosmium walks it.
TEST(IngestPbfStrings, MalformedTagListIsRefusedByTheScanGuard) {
    osmium::memory::Buffer buffer{1024, osmium::memory::Buffer::auto_grow::yes};
    {
        osmium::builder::WayBuilder wb{buffer};
        wb.set_id(42);
        osmium::builder::TagListBuilder tb{wb};
        tb.add_tag("railway", 7, "rail", 4);
        tb.add_tag("a\0b", 3, "c", 1); // "a", "b", "c": three strings
    }
    buffer.commit();
    const auto& way = buffer.get<osmium::Way>(0);
    try {
        check_tag_list("x.osm.pbf", way);
        FAIL() << "accepted a malformed tag list";
    } catch (const InputError& e) {
        EXPECT_NE(std::string{e.what()}.find("x.osm.pbf: OSM way 42: malformed tag list"), std::string::npos)
            << e.what();
    }
}

TEST(IngestPbfStrings, WellFormedTagListPassesTheScanGuard) {
    osmium::memory::Buffer buffer{1024, osmium::memory::Buffer::auto_grow::yes};
    {
        osmium::builder::NodeBuilder nb{buffer};
        nb.set_id(7);
        osmium::builder::TagListBuilder tb{nb};
        tb.add_tag("railway", "signal");
        tb.add_tag("", "");
    }
    buffer.commit();
    EXPECT_NO_THROW(check_tag_list("x.osm", buffer.get<osmium::Node>(0)));
}
