// The embedded sample route: reproducible, readable by libosmium and GDAL, and
// consistent with its own ground truth.
#include "railodd/geometry/alignment.hpp"
#include "railodd/geometry/indexed_alignment.hpp"
#include "railodd/ingest/projection.hpp"
#include "railodd/sample/sample_route.hpp"

#include <gdal.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <osmium/handler.hpp>
#include <osmium/io/xml_input.hpp>
#include <osmium/visitor.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace railodd;

namespace {

// Per process: ctest runs each test case as its own process, possibly in parallel.
fs::path scratch_root(const std::string& name) {
    return fs::temp_directory_path() / "railodd-tests" /
           ("SampleRoute." + name + "." + std::to_string(::getpid()));
}

fs::path scratch(const std::string& name) {
    const fs::path dir = scratch_root(name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct OsmCounts : osmium::handler::Handler {
    std::map<std::string, int> node_railway;
    std::map<std::int64_t, osmium::Location> locations;
    std::map<std::int64_t, std::vector<std::int64_t>> way_nodes;
    std::map<std::int64_t, std::map<std::string, std::string>> way_tags;
    int nodes = 0;
    int relations = 0;
    std::vector<std::pair<std::string, std::string>> route_members; // type:ref, role

    void node(const osmium::Node& n) {
        ++nodes;
        locations[n.id()] = n.location();
        if (const char* r = n.tags()["railway"]) {
            ++node_railway[r];
        }
    }
    void way(const osmium::Way& w) {
        for (const auto& nr : w.nodes()) {
            way_nodes[w.id()].push_back(nr.ref());
        }
        for (const auto& t : w.tags()) {
            way_tags[w.id()][t.key()] = t.value();
        }
    }
    void relation(const osmium::Relation& r) {
        ++relations;
        if (r.tags().has_tag("type", "route") && r.tags().has_tag("route", "train")) {
            for (const auto& m : r.members()) {
                route_members.emplace_back(std::string{osmium::item_type_to_name(m.type())} + ":" +
                                               std::to_string(m.ref()),
                                           m.role());
            }
        }
    }
};

geometry::Alignment alignment_from(const json& track) {
    geometry::Alignment a;
    a.start = {track["start"]["x"], track["start"]["y"], track["start"]["hdg"], 0.0};
    for (const auto& p : track["primitives"]) {
        const std::string kind = p["kind"];
        const auto k = kind == "line" ? geometry::PrimitiveKind::line
                       : kind == "arc" ? geometry::PrimitiveKind::arc
                                       : geometry::PrimitiveKind::spiral;
        a.primitives.push_back({k, p["length"], p["curv_start"], p["curv_end"]});
    }
    return a;
}

// Linear interpolation in the truth's 10 m elevation samples.
double track_elevation(const json& samples, double s) {
    for (std::size_t i = 1; i < samples.size(); ++i) {
        const double s0 = samples[i - 1]["s"], s1 = samples[i]["s"];
        if (s <= s1) {
            const double z0 = samples[i - 1]["z"], z1 = samples[i]["z"];
            return z0 + (z1 - z0) * (s - s0) / (s1 - s0);
        }
    }
    return samples.back()["z"];
}

class Dem {
public:
    explicit Dem(const fs::path& path) {
        GDALAllRegister();
        GDALDatasetH ds = GDALOpen(path.string().c_str(), GA_ReadOnly);
        if (!ds) {
            return;
        }
        GDALGetGeoTransform(ds, gt_);
        cols_ = GDALGetRasterXSize(ds);
        rows_ = GDALGetRasterYSize(ds);
        GDALRasterBandH band = GDALGetRasterBand(ds, 1);
        type_ = GDALGetRasterDataType(band);
        nodata_ = GDALGetRasterNoDataValue(band, &has_nodata_);
        const char* wkt = GDALGetProjectionRef(ds);
        crs_ = wkt ? wkt : "";
        values_.resize(static_cast<std::size_t>(cols_) * rows_);
        if (GDALRasterIO(band, GF_Read, 0, 0, cols_, rows_, values_.data(), cols_, rows_, GDT_Float32, 0, 0) !=
            CE_None) {
            values_.clear();
        }
        GDALClose(ds);
    }
    bool ok() const { return !values_.empty(); }
    // Bilinear between cell centres.
    double at(double lon, double lat) const {
        const double fc = (lon - gt_[0]) / gt_[1] - 0.5;
        const double fr = (lat - gt_[3]) / gt_[5] - 0.5;
        const int c = static_cast<int>(std::floor(fc));
        const int r = static_cast<int>(std::floor(fr));
        const double tc = fc - c, tr = fr - r;
        auto v = [&](int rr, int cc) { return static_cast<double>(values_[static_cast<std::size_t>(rr) * cols_ + cc]); };
        return (1 - tr) * ((1 - tc) * v(r, c) + tc * v(r, c + 1)) + tr * ((1 - tc) * v(r + 1, c) + tc * v(r + 1, c + 1));
    }
    double gt_[6]{};
    int cols_ = 0;
    int rows_ = 0;
    GDALDataType type_ = GDT_Unknown;
    double nodata_ = 0.0;
    int has_nodata_ = 0;
    std::string crs_;
    std::vector<float> values_;
};

class SampleRoute : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        files_ = std::make_unique<sample::SampleFiles>(sample::write_sample_route(scratch("shared")));
        truth_ = std::make_unique<json>(json::parse(slurp(files_->truth)));
        osm_ = std::make_unique<OsmCounts>();
        osmium::io::Reader reader{files_->osm.string()};
        osmium::apply(reader, *osm_);
        reader.close();
    }
    static void TearDownTestSuite() {
        std::error_code ec;
        fs::remove_all(files_->osm.parent_path(), ec);
        fs::remove_all(scratch_root("again"), ec);
        files_.reset();
        truth_.reset();
        osm_.reset();
    }
    static const json& truth() { return *truth_; }
    static const OsmCounts& osm() { return *osm_; }

    static std::unique_ptr<sample::SampleFiles> files_;
    static std::unique_ptr<json> truth_;
    static std::unique_ptr<OsmCounts> osm_;
};

std::unique_ptr<sample::SampleFiles> SampleRoute::files_;
std::unique_ptr<json> SampleRoute::truth_;
std::unique_ptr<OsmCounts> SampleRoute::osm_;

} // namespace

TEST_F(SampleRoute, GenerationIsByteIdentical) {
    const sample::SampleFiles again = sample::write_sample_route(scratch("again"));
    EXPECT_EQ(slurp(files_->osm), slurp(again.osm));
    EXPECT_EQ(slurp(files_->dem), slurp(again.dem));
    EXPECT_EQ(slurp(files_->truth), slurp(again.truth));
    // Nothing besides the three files: no staging leftovers, no GDAL sidecars.
    int entries = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(again.osm.parent_path())) {
        ++entries;
    }
    EXPECT_EQ(entries, 3);
}

TEST_F(SampleRoute, OsmHasTheDesignedFeatures) {
    const auto& n = osm().node_railway;
    EXPECT_EQ(n.at("switch"), 3);
    EXPECT_EQ(n.at("level_crossing"), 1);
    EXPECT_EQ(n.at("station"), 1);
    EXPECT_EQ(n.at("halt"), 1);
    EXPECT_EQ(n.at("buffer_stop"), 1);
    EXPECT_EQ(n.at("signal"), 4);
    EXPECT_EQ(n.at("milestone"), 9);
    EXPECT_EQ(osm().relations, 1);
    int rail = 0, platforms = 0, tunnels = 0, bridges = 0, roads = 0;
    for (const auto& [id, tags] : osm().way_tags) {
        EXPECT_GE(id, 2000000);
        rail += tags.count("railway") && tags.at("railway") == "rail";
        platforms += tags.count("railway") && tags.at("railway") == "platform";
        tunnels += tags.count("tunnel");
        bridges += tags.count("bridge");
        roads += tags.count("highway");
    }
    EXPECT_EQ(rail, 14); // 12 main-line ways, the loop, the spur
    EXPECT_EQ(platforms, 2);
    EXPECT_EQ(tunnels, 1);
    EXPECT_EQ(bridges, 1);
    EXPECT_EQ(roads, 3);
    // Every referenced node exists.
    for (const auto& [id, refs] : osm().way_nodes) {
        for (const auto r : refs) {
            EXPECT_TRUE(osm().locations.count(r)) << "way " << id << " node " << r;
        }
    }
}

TEST_F(SampleRoute, RouteRelationChainsTheMainLine) {
    std::vector<std::int64_t> ways;
    int stops = 0;
    for (const auto& [ref, role] : osm().route_members) {
        if (role == "stop") {
            ++stops;
        } else if (role.empty()) {
            ASSERT_EQ(ref.rfind("way:", 0), 0u) << ref;
            ways.push_back(std::stoll(ref.substr(4)));
        }
    }
    EXPECT_EQ(stops, 2);
    ASSERT_EQ(ways.size(), 12u);
    for (std::size_t i = 1; i < ways.size(); ++i) {
        EXPECT_EQ(osm().way_nodes.at(ways[i - 1]).back(), osm().way_nodes.at(ways[i]).front())
            << "ways " << ways[i - 1] << " and " << ways[i] << " do not share their end node";
    }
}

TEST_F(SampleRoute, CleanNodesLieOnTheTruthAlignment) {
    std::map<std::string, geometry::IndexedAlignment> tracks;
    for (const auto& t : truth()["tracks"]) {
        tracks.emplace(t["name"].get<std::string>(), geometry::IndexedAlignment(alignment_from(t)));
    }
    int checked = 0;
    for (const auto& n : truth()["nodes"]) {
        if (!n.contains("track")) {
            continue;
        }
        const auto& track = tracks.at(n["track"].get<std::string>());
        const double x = n["x"], y = n["y"], s = n["s"], offset = n["offset"];
        const geometry::Projection p = track.project(x, y);
        EXPECT_NEAR(p.s, s, 1e-6) << "node " << n["id"];
        EXPECT_NEAR(p.offset, offset, 1e-6) << "node " << n["id"];
        if (offset == 0.0) {
            EXPECT_LT(p.distance, 1e-6) << "node " << n["id"];
        }
        ++checked;
    }
    EXPECT_GT(checked, 300);
}

TEST_F(SampleRoute, NoiseIsMapperSized) {
    const json& frame = truth()["frame"];
    const ingest::LocalProjection proj({frame["origin_lon"], frame["origin_lat"]});
    double sum2 = 0.0;
    int n = 0;
    for (const auto& node : truth()["nodes"]) {
        const osmium::Location loc = osm().locations.at(node["id"]);
        const ingest::XY p = proj.forward({loc.lon(), loc.lat()});
        sum2 += std::pow(p.x - node["x"].get<double>(), 2) + std::pow(p.y - node["y"].get<double>(), 2);
        ++n;
    }
    const double sigma = std::sqrt(sum2 / (2.0 * n));
    EXPECT_NEAR(sigma, 0.3, 0.05);
}

TEST_F(SampleRoute, DesignCoversTheRequiredGeometry) {
    std::set<std::pair<int, std::string>> curves;
    for (const auto& c : truth()["curves"]) {
        if (c["track"] == "main") {
            curves.insert({static_cast<int>(std::lround(c["radius"].get<double>())), c["direction"]});
        }
    }
    for (const int r : {300, 600, 1200, 2500}) {
        EXPECT_TRUE(curves.count({r, "left"}) || curves.count({r, "right"})) << "no R " << r;
    }
    EXPECT_TRUE(curves.count({2500, "left"}) && curves.count({2500, "right"}));
    const double length = truth()["tracks"][0]["length"];
    EXPECT_GT(length, 8000.0);
    EXPECT_LT(length, 10000.0);
    EXPECT_LE(truth()["elevation"]["max_grade_permille"].get<double>(), 12.0 + 1e-9);
    const json& tunnel = truth()["features"]["tunnels"][0];
    EXPECT_NEAR(tunnel["s_to"].get<double>() - tunnel["s_from"].get<double>(), 600.0, 1e-9);
    const json& bridge = truth()["features"]["bridges"][0];
    EXPECT_NEAR(bridge["s_to"].get<double>() - bridge["s_from"].get<double>(), 150.0, 1e-9);
}

TEST_F(SampleRoute, LevelCrossingIsNearlySquare) {
    const json& lc = truth()["features"]["level_crossings"][0];
    const std::int64_t id = lc["id"];
    int roads_through = 0;
    for (const auto& [way, tags] : osm().way_tags) {
        const auto& refs = osm().way_nodes.at(way);
        if (!tags.count("highway") || std::find(refs.begin(), refs.end(), id) == refs.end()) {
            continue;
        }
        ++roads_through;
        EXPECT_EQ(tags.at("highway"), "secondary");
    }
    EXPECT_EQ(roads_through, 1);
    const double angle = truth()["features"]["crossing_roads"][0]["angle_deg"];
    EXPECT_GE(angle, 70.0);
    EXPECT_LE(angle, 90.0);
}

TEST_F(SampleRoute, DemFollowsTheTrackProfile) {
    const Dem dem(files_->dem);
    ASSERT_TRUE(dem.ok());
    EXPECT_EQ(dem.type_, GDT_Float32);
    EXPECT_TRUE(dem.has_nodata_);
    EXPECT_EQ(dem.nodata_, -32768.0);
    EXPECT_NEAR(dem.gt_[1], 1.0 / 3600.0, 1e-15);
    EXPECT_NE(dem.crs_.find("4326"), std::string::npos);

    const json& f = truth()["features"];
    const double t0 = f["tunnels"][0]["s_from"], t1 = f["tunnels"][0]["s_to"];
    const double b0 = f["bridges"][0]["s_from"], b1 = f["bridges"][0]["s_to"];
    const json& samples = truth()["elevation"]["samples"];
    const double undulation = truth()["dem"]["undulation_amplitude_m"];
    int on_ground = 0;
    for (const auto& n : truth()["nodes"]) {
        if (n.value("track", "") != "main" || n["offset"] != 0.0) {
            continue;
        }
        const double s = n["s"];
        const osmium::Location loc = osm().locations.at(n["id"]);
        const double ground = dem.at(loc.lon(), loc.lat());
        const double z = track_elevation(samples, s);
        if (s > t0 - 200.0 && s < t1 + 200.0) {
            if (s > t0 + 150.0 && s < t1 - 150.0) {
                EXPECT_GT(ground - z, 35.0) << "tunnel at s " << s;
            }
        } else if (s > b0 && s < b1) {
            continue; // the bridge way has no inner nodes; its middle is checked below
        } else {
            EXPECT_NEAR(ground, z, undulation + 0.5) << "s " << s;
            ++on_ground;
        }
    }
    EXPECT_GT(on_ground, 100);

    // The viaduct is straight: its middle lies halfway between its end nodes.
    osmium::Location ends[2];
    for (const auto& n : truth()["nodes"]) {
        if (n.value("track", "") == "main" && (n["s"] == b0 || n["s"] == b1)) {
            ends[n["s"] == b0 ? 0 : 1] = osm().locations.at(n["id"]);
        }
    }
    const double mid_ground = dem.at(0.5 * (ends[0].lon() + ends[1].lon()), 0.5 * (ends[0].lat() + ends[1].lat()));
    EXPECT_LT(mid_ground - track_elevation(samples, 0.5 * (b0 + b1)), -12.0) << "no valley under the bridge";
}

TEST_F(SampleRoute, BranchesMeetTheMainLineAtTheirSwitches) {
    std::map<std::string, geometry::Alignment> tracks;
    for (const auto& t : truth()["tracks"]) {
        tracks[t["name"].get<std::string>()] = alignment_from(t);
    }
    int junctions = 0;
    for (const auto& t : truth()["tracks"]) {
        for (const auto& j : t["junctions"]) {
            const geometry::Pose on_main = geometry::evaluate(tracks.at("main"), j["s"].get<double>());
            const geometry::Pose on_branch = geometry::evaluate(tracks.at(t["name"]), j["at"].get<double>());
            EXPECT_LT(std::hypot(on_main.x - on_branch.x, on_main.y - on_branch.y), 1e-6) << t["name"];
            // Turnouts leave tangentially.
            EXPECT_NEAR(on_main.hdg, on_branch.hdg, 1e-9) << t["name"];
            ++junctions;
        }
    }
    EXPECT_EQ(junctions, 3);
}

TEST_F(SampleRoute, NodesAreSpacedLikeAMapperDrawsThem) {
    std::vector<std::pair<double, double>> curved; // main-line s ranges with curvature
    for (const auto& c : truth()["curves"]) {
        if (c["track"] == "main") {
            curved.emplace_back(c["s_from"].get<double>() - c["transition_in"].get<double>(),
                                c["s_to"].get<double>() + c["transition_out"].get<double>());
        }
    }
    std::vector<double> s;
    for (const auto& n : truth()["nodes"]) {
        if (n.value("track", "") == "main" && n["offset"] == 0.0) {
            s.push_back(n["s"]);
        }
    }
    std::sort(s.begin(), s.end());
    double max_curve_gap = 0.0, max_gap = 0.0;
    for (std::size_t i = 1; i < s.size(); ++i) {
        const double gap = s[i] - s[i - 1];
        const bool in_curve = std::any_of(curved.begin(), curved.end(), [&](const auto& r) {
            return s[i - 1] >= r.first && s[i] <= r.second;
        });
        max_gap = std::max(max_gap, gap);
        if (in_curve) {
            max_curve_gap = std::max(max_curve_gap, gap);
        }
    }
    EXPECT_LE(max_curve_gap, 25.0 + 3.2 + 1e-9); // spacing plus the clearance kept before a fixed node
    EXPECT_LE(max_gap, 450.0);
    EXPECT_GE(max_gap, 150.0); // straights really are sparse
}
