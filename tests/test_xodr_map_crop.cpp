// `railodd crop` on the sample route's map (issue 40): the cut map is a subset
// of the input (ids, lengths and plan views as they were), every named road is
// in it, no link, junction connection, switch or platform names what was cut,
// and it passes validate; bad selections are refused naming the problem.
#include "test_support.hpp"

#include <pugixml.hpp>

#include <map>
#include <set>
#include <string>

using namespace railodd::test;

namespace {

CommandResult run_railodd(const std::string& args) { return run_command(std::string{RAILODD_BIN} + " " + args); }

// The sample route's map, converted once per process.
const fs::path& sample_map() {
    static const fs::path map = [] {
        const fs::path dir = scratch_dir();
        run_railodd("sample -o " + quoted(dir / "s"));
        const auto r = run_railodd("convert " + quoted(dir / "s" / "sample_route.osm") + " -o " + quoted(dir / "m") +
                                   " --no-timings --no-report");
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return dir / "m" / "map.xodr";
    }();
    return map;
}

struct Doc {
    pugi::xml_document xml;
    std::map<std::string, std::string> road_text; // id -> planView as written
    std::set<std::string> roads, junctions;
};

void load(const fs::path& file, Doc& d) {
    ASSERT_TRUE(d.xml.load_file(file.c_str())) << file;
    for (const auto road : d.xml.child("OpenDRIVE").children("road")) {
        std::ostringstream os;
        road.child("planView").print(os);
        d.road_text[road.attribute("id").as_string()] = os.str() + road.attribute("length").as_string();
        d.roads.insert(road.attribute("id").as_string());
    }
    for (const auto j : d.xml.child("OpenDRIVE").children("junction")) {
        d.junctions.insert(j.attribute("id").as_string());
    }
}

// Every reference in the cut map names something in it.
void expect_closed(const Doc& d) {
    const auto root = d.xml.child("OpenDRIVE");
    for (const auto road : root.children("road")) {
        for (const char* end : {"predecessor", "successor"}) {
            const auto l = road.child("link").child(end);
            if (!l) continue;
            const std::string type = l.attribute("elementType").as_string(), id = l.attribute("elementId").as_string();
            EXPECT_TRUE(type == "junction" ? d.junctions.count(id) : d.roads.count(id))
                << "road " << road.attribute("id").as_string() << " " << end << " " << type << " " << id;
        }
        for (const auto sw : road.child("railroad").children("switch")) {
            EXPECT_TRUE(d.roads.count(sw.child("mainTrack").attribute("id").as_string()));
            EXPECT_TRUE(d.roads.count(sw.child("sideTrack").attribute("id").as_string()));
        }
    }
    for (const auto j : root.children("junction")) {
        EXPECT_TRUE(j.child("connection")) << "junction " << j.attribute("id").as_string() << " without a connection";
        for (const auto c : j.children("connection")) {
            EXPECT_TRUE(d.roads.count(c.attribute("incomingRoad").as_string()));
            EXPECT_TRUE(d.roads.count(c.attribute("connectingRoad").as_string()));
        }
    }
    for (const auto st : root.children("station")) {
        for (const auto pf : st.children("platform")) {
            for (const auto g : pf.children("segment")) EXPECT_TRUE(d.roads.count(g.attribute("roadId").as_string()));
        }
    }
}

} // namespace

TEST(XodrMapCrop, ACorridorCutIsAClosedSubsetThatValidates) {
    const fs::path dir = scratch_dir();
    Doc in;
    load(sample_map(), in);
    const auto r = run_railodd("crop " + quoted(sample_map()) + " --roads 2 --corridor 300 -o " + quoted(dir / "cut.xodr"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    Doc cut;
    load(dir / "cut.xodr", cut);
    EXPECT_TRUE(cut.roads.count("2"));
    EXPECT_LT(cut.roads.size(), in.roads.size());
    EXPECT_GT(cut.roads.size(), 1u); // the corridor brings neighbours
    for (const auto& [id, text] : cut.road_text) {
        ASSERT_TRUE(in.road_text.count(id)) << "road " << id << " is not in the input";
        EXPECT_EQ(text, in.road_text.at(id)) << "road " << id << " changed";
    }
    expect_closed(cut);
    const auto v = run_railodd("validate " + quoted(dir / "cut.xodr"));
    EXPECT_EQ(v.exit_code, 0) << v.output;
}

TEST(XodrMapCrop, NamedRoadsAloneDropTheirLinksCleanly) {
    const fs::path dir = scratch_dir();
    const auto r = run_railodd("crop " + quoted(sample_map()) + " --roads 1,2 -o " + quoted(dir / "cut.xodr"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    Doc cut;
    load(dir / "cut.xodr", cut);
    EXPECT_TRUE(cut.roads.count("1") && cut.roads.count("2"));
    expect_closed(cut);
    EXPECT_EQ(run_railodd("validate " + quoted(dir / "cut.xodr")).exit_code, 0);
}

TEST(XodrMapCrop, BadSelectionsAreRefusedAndWriteNothing) {
    const fs::path dir = scratch_dir();
    const auto unknown = run_railodd("crop " + quoted(sample_map()) + " --roads 99999 -o " + quoted(dir / "a.xodr"));
    EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("road 99999 is not in the map"), std::string::npos) << unknown.output;
    EXPECT_FALSE(fs::exists(dir / "a.xodr"));
    const auto none = run_railodd("crop " + quoted(sample_map()) + " -o " + quoted(dir / "b.xodr"));
    EXPECT_EQ(none.exit_code, 1) << none.output;
    const auto box = run_railodd("crop " + quoted(sample_map()) + " --box 1,2,0,5 -o " + quoted(dir / "c.xodr"));
    EXPECT_EQ(box.exit_code, 1) << box.output;
    const auto empty = run_railodd("crop " + quoted(sample_map()) + " --box 1e7,1e7,1.1e7,1.1e7 -o " + quoted(dir / "d.xodr"));
    EXPECT_EQ(empty.exit_code, 2) << empty.output;
    EXPECT_NE(empty.output.find("keeps no road"), std::string::npos) << empty.output;
    EXPECT_FALSE(fs::exists(dir / "d.xodr"));
}
