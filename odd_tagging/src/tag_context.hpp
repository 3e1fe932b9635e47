#pragma once
// What the taggers share: the inputs, the taxonomy, and how an s-range of a
// track-graph edge becomes tagged elements on the roads it was written as.
#include "railodd/odd/tagger.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace railodd::odd {

// A way's stretch of an edge, along the edge's fitted alignment.
struct WayRange {
    double s0 = 0.0;
    double s1 = 0.0;
    const ingest::Way* way = nullptr;
};

class TagContext {
public:
    TagContext(const TaggerInput& in, const Taxonomy& taxonomy, OddProfile& out);

    const xodr::MapInput& geo() const { return in_.map_input; }
    const xodr::MapBuild& map() const { return in_.map; }
    const Taxonomy& taxonomy() const { return taxonomy_; }
    bool written(std::size_t edge) const { return !in_.map.rail.pieces[edge].empty(); }
    const geometry::IndexedAlignment& alignment(std::size_t edge);
    const std::vector<WayRange>& ways(std::size_t edge); // ascending s
    const ingest::Feature* feature_at_node(std::int64_t node_id) const;

    // Tags [s0, s1] of an edge (s0 == s1: a point), split over its roads.
    // Attributes are classified through the taxonomy: a number attribute
    // with bins also gets NAME_class.
    void tag(const std::string& path, std::size_t edge, double s0, double s1, std::vector<TaggedAttribute> attributes,
             std::vector<std::string> osm_ids, const std::string& source);
    void unparsed(std::vector<std::string> osm_ids, const std::string& tag, const std::string& value,
                  const std::string& reason);

    // OSM ids of the ways covering [s0, s1] of an edge.
    std::vector<std::string> way_ids(std::size_t edge, double s0, double s1);

    // Puts the profile's elements in order: by track, chainage, element path
    // and end chainage, equal keys in tagging order.
    void sort_elements();

private:
    const TaggerInput& in_;
    const Taxonomy& taxonomy_;
    OddProfile& out_;
    std::map<std::size_t, std::unique_ptr<geometry::IndexedAlignment>> alignments_;
    std::map<std::size_t, std::vector<WayRange>> ways_;
    std::map<std::int64_t, const ingest::Way*> way_by_id_;
    std::map<std::int64_t, const ingest::Feature*> node_features_;
};

void tag_horizontal(TagContext& ctx);     // straights, transition curves, curves (tag_geometry.cpp)
void tag_vertical_and_cant(TagContext& ctx); // gradient classes, cant (tag_geometry.cpp)
void tag_track_count(TagContext& ctx);    // single / double / multiple (tag_track_count.cpp)
void tag_way_attributes(TagContext& ctx); // gauge, electrification, speed, usage, service, direction (tag_ways.cpp)
void tag_features(TagContext& ctx);       // switches, crossings, structures, stations, signals, ... (tag_features.cpp)
void tag_surroundings(TagContext& ctx);   // roads running alongside (tag_surroundings.cpp)
void tag_land_use(TagContext& ctx);       // land-use areas holding the track (tag_landuse.cpp)

} // namespace railodd::odd
