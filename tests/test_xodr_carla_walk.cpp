// CARLA 0.9.16's own OpenDRIVE loader (../shared/tools/carla-road, LibCarla's
// carla::opendrive + carla::road, built out of tree) on our maps (issue 38):
// the sample route's map and Liechtenstein load, every rail lane is found on
// its own road by GetWaypoint(Rail), the sample's main line is walked end to
// end in both directions through all its junctions with GetNext / GetPrevious,
// every rail road is reached from the main line, and no step jumps by more
// than 1 m in position or height. The library is only the reader: the walks
// are ours, so that what "walkable" means is written here.
//
// Compiled as C++17 with LibCarla's flags (not the project's C++20), so it
// includes no project header except test_support.hpp (plain C++17) and runs
// the railodd executable to make the maps.
#include "test_support.hpp"

#include "carla/geom/Location.h"
#include "carla/geom/Math.h"
#include "carla/opendrive/OpenDriveParser.h"
#include "carla/road/Map.h"

#include <nlohmann/json.hpp>
#include <pugixml/pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <deque>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <tuple>
#include <vector>

using namespace railodd::test;

namespace {

namespace cr = carla::road;
using carla::geom::Location;
using cr::element::Waypoint;

constexpr auto kRail = static_cast<int32_t>(cr::Lane::LaneType::Rail);
constexpr double kWalkStep = 2.0;   // m, the walk's GetNext / GetPrevious distance
constexpr double kReachStep = 5.0;  // m, the reachability search's step
constexpr double kMaxJump = 1.0;    // m, over the step length, and in height
constexpr double kTouch = 1.0;      // m, two road ends this close are linked in the plan

// ---------------------------------------------------------------------------
// What our map and its input say, read without CARLA (the reference the
// loader's answers are compared with).

struct XodrRoad {
    cr::RoadId id = 0;
    int junction = -1;
    double length = 0;
    std::vector<cr::LaneId> rail_lanes;
    std::set<long long> ways; // OSM way ids from <userData code="osm">
    double x0 = 0, y0 = 0, hdg0 = 0; // the plan view's first point
    double offset0 = 0;              // the lane offset at s = 0 (our rail lane's centre on the track)
};

void add_osm_ways(const std::string& value, std::set<long long>& ways) {
    std::istringstream in(value);
    for (std::string item; std::getline(in, item, ',');) {
        if (item.rfind("way:", 0) == 0) {
            ways.insert(std::stoll(item.substr(4)));
        }
    }
}

// Roads with at least one lane of type "rail", by id.
std::map<cr::RoadId, XodrRoad> read_rail_roads(const std::string& xodr) {
    pugi::xml_document doc;
    doc.load_string(xodr.c_str());
    std::map<cr::RoadId, XodrRoad> roads;
    for (const auto& road : doc.child("OpenDRIVE").children("road")) {
        XodrRoad r;
        r.id = road.attribute("id").as_uint();
        r.junction = road.attribute("junction").as_int(-1);
        r.length = road.attribute("length").as_double();
        for (const auto& section : road.child("lanes").children("laneSection")) {
            for (const auto& side : section.children()) {
                for (const auto& lane : side.children("lane")) {
                    const auto id = lane.attribute("id").as_int();
                    if (std::string{lane.attribute("type").value()} == "rail" &&
                        std::find(r.rail_lanes.begin(), r.rail_lanes.end(), id) == r.rail_lanes.end()) {
                        r.rail_lanes.push_back(id);
                    }
                }
            }
        }
        for (const auto& ud : road.children("userData")) {
            if (std::string{ud.attribute("code").value()} == "osm") {
                add_osm_ways(ud.attribute("value").value(), r.ways);
            }
        }
        const auto g = road.child("planView").child("geometry");
        r.x0 = g.attribute("x").as_double();
        r.y0 = g.attribute("y").as_double();
        r.hdg0 = g.attribute("hdg").as_double();
        r.offset0 = road.child("lanes").child("laneOffset").attribute("a").as_double();
        if (!r.rail_lanes.empty()) {
            roads[r.id] = r;
        }
    }
    return roads;
}

// The track ways of the input's train route relations (platforms and stops
// left out): the main line.
std::set<long long> route_ways(const fs::path& osm) {
    std::set<long long> ways;
    pugi::xml_document doc;
    if (osm.extension() != ".osm" || !doc.load_file(osm.c_str())) {
        return ways; // a .pbf: its walks are reported, not checked against a route
    }
    for (const auto& rel : doc.child("osm").children("relation")) {
        const auto route = rel.find_child_by_attribute("tag", "k", "route");
        if (std::string{route.attribute("v").value()} != "train") {
            continue;
        }
        for (const auto& m : rel.children("member")) {
            const std::string role = m.attribute("role").value();
            if (std::string{m.attribute("type").value()} == "way" && role.rfind("platform", 0) != 0 &&
                role != "stop") {
                ways.insert(m.attribute("ref").as_llong());
            }
        }
    }
    return ways;
}

// The route's length as report.json's fitted tracks give it: the tracks made
// of route ways only.
double route_length(const fs::path& report, const std::set<long long>& ways) {
    const auto r = nlohmann::json::parse(read_file(report));
    double length = 0;
    for (const auto& t : r["geometry"]["tracks"]) {
        const auto& w = t["osm_ways"];
        if (std::all_of(w.begin(), w.end(), [&](const auto& id) { return ways.count(id.template get<long long>()); })) {
            length += t["length_m"].get<double>();
        }
    }
    return length;
}

// ---------------------------------------------------------------------------
// Small geometry on CARLA's answers.

Location at(const cr::Map& map, const Waypoint& w) { return map.ComputeTransform(w).location; }

// In plan: heights are checked on their own.
double distance(const Location& a, const Location& b) {
    return static_cast<double>(carla::geom::Math::Distance2D(a, b));
}

std::string describe(const Waypoint& w) {
    std::ostringstream s;
    s << "road " << w.road_id << " lane " << w.lane_id << " s=" << std::round(w.s * 10) / 10;
    return s.str();
}

// The worst position and height step seen between consecutive waypoints.
struct Jumps {
    double position = 0; // |plan distance - step|
    double height = 0;   // |dz|
    std::string position_at, height_at;

    void add(const cr::Map& map, const Waypoint& from, const Waypoint& to, double step) {
        const Location a = at(map, from), b = at(map, to);
        const double p = std::abs(distance(a, b) - step), h = std::abs(static_cast<double>(b.z - a.z));
        if (p > position) {
            position = p;
            position_at = describe(from) + " -> " + describe(to);
        }
        if (h > height) {
            height = h;
            height_at = describe(from) + " -> " + describe(to);
        }
    }
};

enum class Dir { Next, Previous };

std::vector<Waypoint> advance(const cr::Map& map, const Waypoint& w, Dir dir, double step) {
    return dir == Dir::Next ? map.GetNext(w, step) : map.GetPrevious(w, step);
}

// ---------------------------------------------------------------------------
// The walk: one train along the straightest way (the main line's roads first,
// where known), counting what it passes.

struct Walk {
    double length = 0;
    int steps = 0;
    int junctions = 0;           // junction entries
    std::vector<cr::RoadId> roads; // in the order driven
    Jumps jumps;
    Waypoint last;
    std::string error; // a LibCarla exception, if one ended the walk
};

// The candidate that keeps closest to the heading; roads in `preferred`
// first (at a switch both branches are nearly straight for the first metres).
Waypoint straightest(const cr::Map& map, const Location& here, const Location& heading,
                     const std::vector<Waypoint>& candidates, const std::set<cr::RoadId>& preferred) {
    auto score = [&](const Waypoint& c) {
        const Location d = at(map, c) - here;
        const double n = std::max(1e-9, static_cast<double>(d.Length()));
        const double cosine = (d.x * heading.x + d.y * heading.y + d.z * heading.z) / n;
        return std::make_pair(preferred.count(c.road_id) ? 0 : 1, -cosine);
    };
    return *std::min_element(candidates.begin(), candidates.end(),
                             [&](const Waypoint& a, const Waypoint& b) { return score(a) < score(b); });
}

Walk walk(const cr::Map& map, const Waypoint& start, Dir dir, const std::set<cr::RoadId>& preferred, int max_steps) {
    Walk w;
    w.last = start;
    w.roads.push_back(start.road_id);
    Location heading{};
    try {
        for (; w.steps < max_steps; ++w.steps) {
            const auto next = advance(map, w.last, dir, kWalkStep);
            if (next.empty()) {
                break; // a track end, or a link CARLA does not follow
            }
            const Location here = at(map, w.last);
            const Waypoint c = straightest(map, here, heading, next, preferred);
            w.jumps.add(map, w.last, c, kWalkStep);
            w.length += distance(here, at(map, c));
            const auto j = map.GetJunctionId(c.road_id);
            if (j >= 0 && j != map.GetJunctionId(w.last.road_id)) {
                ++w.junctions;
            }
            if (c.road_id != w.roads.back()) {
                w.roads.push_back(c.road_id);
            }
            heading = at(map, c) - here;
            w.last = c;
        }
    } catch (const std::exception& e) {
        w.error = e.what();
    }
    return w;
}

std::string road_list(const std::vector<cr::RoadId>& roads) {
    std::string s;
    for (const auto r : roads) {
        s += (s.empty() ? "" : ",") + std::to_string(r);
    }
    return s;
}

// ---------------------------------------------------------------------------
// Track ends: rail lane ends that no other rail road's end touches (buffer
// stops and the extract's edge), one per road end.

struct End {
    Waypoint wp;
    Location loc;
    bool at_start = false;
};

std::vector<End> lane_ends(const cr::Map& map, const std::map<cr::RoadId, XodrRoad>& rail) {
    std::vector<End> ends;
    for (const auto& [id, r] : rail) {
        for (const bool start : {true, false}) {
            // GetWaypoint takes s < length only.
            const auto s = static_cast<float>(start ? 0.0 : r.length - 0.01);
            if (const auto wp = map.GetWaypoint(id, r.rail_lanes.front(), s)) {
                ends.push_back({*wp, at(map, *wp), start});
            }
        }
    }
    return ends;
}

std::vector<End> free_ends(const cr::Map& map, const std::map<cr::RoadId, XodrRoad>& rail) {
    const auto ends = lane_ends(map, rail);
    std::vector<End> free;
    for (const auto& e : ends) {
        const bool touched = std::any_of(ends.begin(), ends.end(), [&](const End& o) {
            return o.wp.road_id != e.wp.road_id && distance(o.loc, e.loc) < kTouch;
        });
        if (!touched) {
            free.push_back(e);
        }
    }
    return free;
}

// GetNext or GetPrevious, whichever leads from this end into its road: CARLA
// fixes a lane's direction by its id's sign, so ask it on the road's middle.
Dir inward(const cr::Map& map, const End& e, double length) {
    const auto mid = map.GetWaypoint(e.wp.road_id, e.wp.lane_id, static_cast<float>(length / 2));
    const auto n = mid ? map.GetNext(*mid, 1.0) : std::vector<Waypoint>{};
    const bool next_increases_s = !n.empty() && n.front().road_id == mid->road_id && n.front().s > mid->s;
    return e.at_start == next_increases_s ? Dir::Next : Dir::Previous;
}

// ---------------------------------------------------------------------------
// Reachability: breadth-first over waypoints, GetNext and GetPrevious, from
// seeds; which roads it reaches and the jumps on the way.

struct Reach {
    std::set<cr::RoadId> roads;
    std::size_t waypoints = 0;
    Jumps jumps;
    int duplicates = 0; // one lane listed twice as a successor (two connections per junction road)
    std::string duplicate_at;
    bool capped = false;
    std::string error;
};

void count_duplicates(const std::vector<Waypoint>& next, Reach& r) {
    for (std::size_t i = 0; i < next.size(); ++i) {
        for (std::size_t k = i + 1; k < next.size(); ++k) {
            if (next[i].road_id == next[k].road_id && next[i].lane_id == next[k].lane_id &&
                std::abs(next[i].s - next[k].s) < 1e-3) {
                ++r.duplicates;
                r.duplicate_at = describe(next[i]);
            }
        }
    }
}

Reach explore(const cr::Map& map, const std::vector<Waypoint>& seeds, std::size_t max_waypoints) {
    Reach r;
    // s rounded to 1 m: entries from different links start different grids
    // on a road, a handful at most.
    using Key = std::tuple<cr::RoadId, cr::SectionId, cr::LaneId, long>;
    auto key = [](const Waypoint& w) { return Key{w.road_id, w.section_id, w.lane_id, std::lround(w.s)}; };
    std::set<Key> seen;
    std::deque<Waypoint> queue;
    for (const auto& s : seeds) {
        if (seen.insert(key(s)).second) {
            queue.push_back(s);
        }
    }
    try {
        while (!queue.empty() && !(r.capped = seen.size() > max_waypoints)) {
            const Waypoint w = queue.front();
            queue.pop_front();
            r.roads.insert(w.road_id);
            for (const Dir d : {Dir::Next, Dir::Previous}) {
                const auto next = advance(map, w, d, kReachStep);
                count_duplicates(next, r);
                for (const auto& c : next) {
                    r.jumps.add(map, w, c, kReachStep);
                    if (seen.insert(key(c)).second) {
                        queue.push_back(c);
                    }
                }
            }
        }
    } catch (const std::exception& e) {
        r.error = e.what();
    }
    r.waypoints = seen.size();
    return r;
}

// ---------------------------------------------------------------------------
// The maps: made by railodd from the sample route and from Liechtenstein,
// loaded by CARLA.

struct MapCase {
    const char* name;
    bool sample; // the embedded sample route, else a ../shared/data extract
    const char* extract;
};

// gtest names the case in messages, not its bytes.
void PrintTo(const MapCase& c, std::ostream* os) { *os << c.name; }

class CarlaWalk : public ::testing::TestWithParam<MapCase> {
protected:
    void SetUp() override {
        const MapCase c = GetParam();
        if (!c.sample) {
            RAILODD_REQUIRE_SHARED_DATA();
        }
        const fs::path dir = scratch_dir();
        if (c.sample) {
            const auto made = run_command(std::string{RAILODD_BIN} + " sample -o " + quoted(dir / "in"));
            ASSERT_EQ(made.exit_code, 0) << made.output;
            input_ = dir / "in" / "sample_route.osm";
        } else {
            input_ = shared_data() / "osm" / c.extract;
        }
        out_ = dir / "out";
        const auto conv = run_command(std::string{RAILODD_BIN} + " convert " + quoted(input_) + " -o " + quoted(out_) +
                                      " --no-timings --no-report");
        ASSERT_EQ(conv.exit_code, 0) << conv.output;
        const std::string xodr = read_file(out_ / "map.xodr");
        rail_ = read_rail_roads(xodr);
        ASSERT_FALSE(rail_.empty()) << "no rail lane in " << out_ / "map.xodr";
        // LibCarla logs its warnings and errors on stdout / stderr.
        ::testing::internal::CaptureStdout();
        ::testing::internal::CaptureStderr();
        map_ = carla::opendrive::OpenDriveParser::Load(xodr);
        load_log_ = ::testing::internal::GetCapturedStdout() + ::testing::internal::GetCapturedStderr();
        ASSERT_TRUE(map_.has_value()) << "CARLA could not load " << out_ / "map.xodr" << ": " << load_log_;
    }

    const cr::Map& map() const { return *map_; }

    // A figure on stdout (ctest --output-on-failure, -V) and in the XML report
    // (its key an XML attribute name).
    void figure(const std::string& key, const std::string& value) {
        std::cout << "[carla " << GetParam().name << "] " << key << ": " << value << "\n";
        std::string attribute = key;
        std::replace_if(attribute.begin(), attribute.end(), [](unsigned char ch) { return !std::isalnum(ch); }, '_');
        RecordProperty(attribute, value);
    }

    // The longest rail road outside junctions: on the main line on both maps.
    Waypoint longest_road_middle() const {
        const XodrRoad* best = nullptr;
        for (const auto& [id, r] : rail_) {
            if (r.junction < 0 && (!best || r.length > best->length)) {
                best = &r;
            }
        }
        return *map().GetWaypoint(best->id, best->rail_lanes.front(), static_cast<float>(best->length / 2));
    }

    int max_steps() const {
        double total = 0;
        for (const auto& [id, r] : rail_) {
            total += r.length;
        }
        return static_cast<int>(total / kWalkStep) + 100; // a loop ends here
    }

    void expect_no_jumps(const std::string& what, const Jumps& j) {
        std::ostringstream s;
        s << "position " << j.position << " m" << (j.position_at.empty() ? "" : " (" + j.position_at + ")")
          << ", height " << j.height << " m" << (j.height_at.empty() ? "" : " (" + j.height_at + ")");
        figure(what + " max jump", s.str());
        EXPECT_LT(j.position, kMaxJump) << what << ": " << s.str();
        EXPECT_LT(j.height, kMaxJump) << what << ": " << s.str();
    }

    Walk report_walk(const std::string& label, const End& from, const std::set<cr::RoadId>& preferred) {
        const Dir d = inward(map(), from, rail_.at(from.wp.road_id).length);
        const Walk w = walk(map(), from.wp, d, preferred, max_steps());
        std::ostringstream s;
        s << (d == Dir::Next ? "GetNext" : "GetPrevious") << " from " << describe(from.wp) << ": "
          << std::round(w.length) << " m, " << w.steps << " steps, " << w.junctions << " junctions, ended at "
          << describe(w.last) << ", roads " << road_list(w.roads) << (w.error.empty() ? "" : ", error: ") << w.error;
        figure(label, s.str());
        EXPECT_TRUE(w.error.empty()) << label << ": " << w.error;
        expect_no_jumps(label, w.jumps);
        return w;
    }

    fs::path input_, out_;
    std::map<cr::RoadId, XodrRoad> rail_;
    boost::optional<cr::Map> map_;
    std::string load_log_;
};

// Rail roads whose OSM ways are all route ways: the main line and its
// junction roads.
std::set<cr::RoadId> main_line_roads(const std::map<cr::RoadId, XodrRoad>& rail, const std::set<long long>& ways) {
    std::set<cr::RoadId> roads;
    for (const auto& [id, r] : rail) {
        if (!r.ways.empty() && std::includes(ways.begin(), ways.end(), r.ways.begin(), r.ways.end())) {
            roads.insert(id);
        }
    }
    return roads;
}

} // namespace

// Loads with no warning; every rail lane is LaneType::Rail and found on its
// own road by GetWaypoint(Rail) at its centre line mid-road; CARLA puts each
// road's plan view where we wrote it, y negated.
TEST_P(CarlaWalk, LoadsAndFindsEveryRailLaneOnItsOwnRoad) {
    EXPECT_EQ(load_log_.find("WARNING"), std::string::npos) << load_log_;
    EXPECT_EQ(load_log_.find("ERROR"), std::string::npos) << load_log_;
    int lanes = 0, found = 0;
    for (const auto& [id, r] : rail_) {
        const auto ref = map().GetWaypoint(id, 0, 0.0f);
        ASSERT_TRUE(ref) << "road " << id << " missing in CARLA's map";
        // Lane 0 is the reference line moved left by the lane offset.
        const double x = r.x0 - r.offset0 * std::sin(r.hdg0), y = r.y0 + r.offset0 * std::cos(r.hdg0);
        EXPECT_LT(distance(at(map(), *ref), Location(x, -y, 0)), 0.01) << "road " << id << " starts elsewhere";
        for (const auto lane : r.rail_lanes) {
            ++lanes;
            const auto mid = map().GetWaypoint(id, lane, static_cast<float>(r.length / 2));
            ASSERT_TRUE(mid) << "road " << id << " lane " << lane;
            EXPECT_EQ(map().GetLaneType(*mid), cr::Lane::LaneType::Rail) << "road " << id << " lane " << lane;
            const auto q = map().GetWaypoint(at(map(), *mid), kRail);
            const bool own = q && q->road_id == id && q->lane_id == lane;
            found += own ? 1 : 0;
            EXPECT_TRUE(own) << "GetWaypoint(Rail) at road " << id << " lane " << lane << " s=" << r.length / 2
                             << " gave " << (q ? describe(*q) : std::string{"nothing"});
        }
    }
    figure("rail lanes found on their own road", std::to_string(found) + "/" + std::to_string(lanes));
}

// The sample's main line (its route relation) from each end to the other,
// GetNext one way and GetPrevious the other, through all its junctions, for
// its whole length. Where the input has no route relation (Liechtenstein)
// every track end's walk is reported and only the jumps are checked.
TEST_P(CarlaWalk, WalksTheMainLineEndToEndBothWays) {
    const auto ways = route_ways(input_);
    const auto main = main_line_roads(rail_, ways);
    std::vector<End> ends;
    for (const auto& e : free_ends(map(), rail_)) {
        if (main.empty() || main.count(e.wp.road_id)) {
            ends.push_back(e);
        }
    }
    figure("track ends", std::to_string(ends.size()));
    std::vector<Walk> walks;
    for (std::size_t i = 0; i < ends.size(); ++i) {
        walks.push_back(report_walk("walk " + std::to_string(i + 1), ends[i], main));
    }
    if (main.empty()) {
        return;
    }
    ASSERT_EQ(ends.size(), 2u) << "the main line has two ends";
    const double length = route_length(out_ / "report.json", ways);
    std::set<int> junctions;
    for (const auto id : main) {
        if (rail_.at(id).junction >= 0) {
            junctions.insert(rail_.at(id).junction);
        }
    }
    figure("main line", std::to_string(std::lround(length)) + " m in report.json, " +
                            std::to_string(junctions.size()) + " junctions, roads " +
                            road_list({main.begin(), main.end()}));
    for (std::size_t i = 0; i < 2; ++i) {
        const Walk& w = walks[i];
        EXPECT_NEAR(w.length, length, 0.03 * length) << "walk " << i + 1 << " stopped at " << describe(w.last);
        EXPECT_GE(w.junctions, static_cast<int>(junctions.size())) << "walk " << i + 1;
        // A dead end leaves less than one step of track.
        EXPECT_LT(distance(at(map(), w.last), ends[1 - i].loc), kWalkStep + kMaxJump)
            << "walk " << i + 1 << " ended at " << describe(w.last) << ", not at " << describe(ends[1 - i].wp);
    }
}

// Every rail road, every switch's diverging track included, reached from the
// main line's longest road going both ways through the lane graph.
TEST_P(CarlaWalk, ReachesEveryRailRoadFromTheMainLine) {
    const Waypoint seed = longest_road_middle();
    // At most a few 1 m grids per lane (see explore): far below this cap.
    const Reach r = explore(map(), {seed}, static_cast<std::size_t>(max_steps() * kWalkStep * 4));
    std::string missing;
    for (const auto& [id, road] : rail_) {
        if (!r.roads.count(id)) {
            missing += (missing.empty() ? "" : ",") + std::to_string(id);
        }
    }
    std::size_t reached = 0;
    for (const auto id : r.roads) {
        reached += rail_.count(id);
    }
    figure("reached", "from " + describe(seed) + ": " + std::to_string(reached) + "/" + std::to_string(rail_.size()) +
                                                 " rail roads, " + std::to_string(r.waypoints) + " waypoints" +
                                                 (missing.empty() ? "" : ", not reached: " + missing));
    EXPECT_TRUE(r.error.empty()) << r.error;
    EXPECT_FALSE(r.capped) << "the search did not end";
    figure("duplicate successors", std::to_string(r.duplicates) + (r.duplicates ? " (" + r.duplicate_at + ")" : ""));
    EXPECT_EQ(r.duplicates, 0) << "a waypoint listed twice among GetNext / GetPrevious, last at " << r.duplicate_at;
    expect_no_jumps("reach", r.jumps);
    // Both maps are one connected rail network in the data: every road.
    EXPECT_TRUE(missing.empty()) << "rail roads not reached from the main line: " << missing;
}

INSTANTIATE_TEST_SUITE_P(Maps, CarlaWalk,
                         ::testing::Values(MapCase{"sample", true, ""},
                                           MapCase{"liechtenstein", false, "valhalla_liechtenstein-latest.osm.pbf"}),
                         [](const ::testing::TestParamInfo<MapCase>& info) { return std::string{info.param.name}; });
