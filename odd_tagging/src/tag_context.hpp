#pragma once
// What the taggers share: the inputs, the taxonomy, and how an s-range of a
// track-graph edge becomes tagged elements on the roads it was written as.
#include "railodd/odd/tagger.hpp"

#include "railodd/geometry/indexed_alignment.hpp"

#include <functional>
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

    // The network is tagged a batch of tracks (graph edges) at a time, so
    // that only one batch's elements are held: the taggers tag the edges in
    // [first(), last()) and tag() drops any other.
    void set_batch(std::size_t first, std::size_t last);
    std::size_t first() const { return first_; }
    std::size_t last() const { return last_; }
    bool in_batch(std::size_t edge) const { return edge >= first_ && edge < last_; }
    // Drops the batch's cached alignments and way ranges.
    void end_batch();
    // What a tagger builds once for the whole network (a grid of every
    // track's samples, the land-use index), kept for the later batches.
    template <class T>
    const T& prepared(const std::string& key, const std::function<T()>& make) {
        auto& slot = prepared_[key];
        if (!slot) {
            slot = std::make_shared<T>(make());
        }
        return *static_cast<const T*>(slot.get());
    }

    const xodr::MapInput& geo() const { return in_.map_input; }
    const xodr::MapBuild& map() const { return in_.map; }
    const Taxonomy& taxonomy() const { return taxonomy_; }
    bool written(std::size_t edge) const { return !in_.map.rail.pieces[edge].empty(); }
    const geometry::IndexedAlignment& alignment(std::size_t edge);
    // Every track's alignment in turn, for what a tagger prepares over the
    // whole network: each is made and dropped in turn unless prebuilt, so
    // that the network's indexes are never all held at once, and made for
    // length() and evaluate() only (IndexedAlignment::for_evaluation).
    void for_each_alignment(const std::function<void(std::size_t, const geometry::IndexedAlignment&)>& f) const;
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

    // Puts the batch's elements in order: by track, chainage, element path
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
    std::map<std::string, std::shared_ptr<void>> prepared_;
    std::size_t first_ = 0;
    std::size_t last_ = 0;
};

void tag_horizontal(TagContext& ctx);     // straights, transition curves, curves (tag_geometry.cpp)
void tag_vertical_and_cant(TagContext& ctx); // gradient classes, cant (tag_geometry.cpp)
void tag_track_count(TagContext& ctx);    // single / double / multiple (tag_track_count.cpp)
void tag_way_attributes(TagContext& ctx); // gauge, electrification, speed, usage, service, direction (tag_ways.cpp)
void tag_features(TagContext& ctx);       // switches, crossings, structures, stations, signals, ... (tag_features.cpp)
void tag_surroundings(TagContext& ctx);   // roads running alongside (tag_surroundings.cpp)
void tag_land_use(TagContext& ctx);       // land-use areas holding the track (tag_landuse.cpp)

} // namespace railodd::odd
