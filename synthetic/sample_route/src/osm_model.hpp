#pragma once
// In-memory OSM elements of the sample route, each remembering where it was
// designed (clean local position, track and chainage), so the OSM file and the
// ground truth are written from the same objects.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace railodd::sample {

// Ordered, so the XML lists tags in the order the design states them.
using Tags = std::vector<std::pair<std::string, std::string>>;

// Where on a designed track a node was placed.
struct Placement {
    std::string track;   // "main", "loop", "spur"
    double s = 0.0;      // chainage along that track's alignment, m
    double offset = 0.0; // lateral, left positive, m (0 for track nodes)
};

struct OsmNode {
    std::int64_t id = 0;
    double x = 0.0; // clean local position, m
    double y = 0.0;
    double lon = 0.0; // written position: clean plus mapping noise
    double lat = 0.0;
    Tags tags;
    std::optional<Placement> placement; // empty for nodes off every track (roads)
};

struct OsmWay {
    std::int64_t id = 0;
    std::vector<std::int64_t> nodes;
    Tags tags;
    std::string kind;  // "track", "platform", "road"
    std::string track; // designed track it belongs to or runs beside; empty for roads off it
    double s_from = 0.0;
    double s_to = 0.0;
};

struct OsmMember {
    std::string type; // "node", "way"
    std::int64_t ref = 0;
    std::string role;
};

struct OsmRelation {
    std::int64_t id = 0;
    std::vector<OsmMember> members;
    Tags tags;
};

struct OsmData {
    std::vector<OsmNode> nodes;
    std::vector<OsmWay> ways;
    std::vector<OsmRelation> relations;
};

} // namespace railodd::sample
