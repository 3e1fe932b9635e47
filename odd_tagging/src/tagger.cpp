#include "railodd/odd/tagger.hpp"

#include "tag_context.hpp"

#include "railodd/odd/profile_summary.hpp"

#include <algorithm>
#include <iterator>
#include <set>
#include <stdexcept>
#include <tuple>
#include <sstream>

namespace railodd::odd {

namespace {

std::string text_of(const AttributeValue& v) {
    if (const double* d = std::get_if<double>(&v)) {
        std::ostringstream os;
        os.precision(6);
        os << *d;
        return os.str();
    }
    if (const bool* b = std::get_if<bool>(&v)) {
        return *b ? "true" : "false";
    }
    return std::get<std::string>(v);
}

// Where track e starts and ends: chainage runs along the alignment, which may
// run against the graph edge's node order.
TrackEnd track_end(const TaggerInput& input, std::size_t e, const geometry::IndexedAlignment& a) {
    const auto& edge = input.map_input.geometry.tracks.edges[e];
    const auto& v = input.map_input.geometry.tracks.vertices;
    const bool against = input.map_input.geometry.fitted_tracks.edges[e].reversed;
    const std::size_t from = against ? edge.to : edge.from, to = against ? edge.from : edge.to;
    return {e, v[from].node_id, v[to].node_id, a.evaluate(0.0).hdg, a.evaluate(a.length()).hdg};
}

} // namespace

namespace {

// Everything but the elements: what the route is and where its tracks end.
OddProfile profile_head(const TaggerInput& input, const Taxonomy& taxonomy, const TagContext& ctx) {
    OddProfile p;
    p.taxonomy_name = taxonomy.name;
    p.taxonomy_version = taxonomy.version;
    p.taxonomy_file = taxonomy.source;
    p.route = input.map_input.ingest.source + " (" + input.map_input.ingest.selection + ")";
    ctx.for_each_alignment([&](std::size_t e, const geometry::IndexedAlignment& a) {
        if (ctx.written(e)) {
            p.length_m += a.length();
            ++p.tracks;
            p.track_ends.push_back(track_end(input, e, a));
        }
    });
    return p;
}

} // namespace

void tag_network(const TaggerInput& input, const Taxonomy& taxonomy, ProfileSink& sink,
                 std::size_t tracks_per_batch) {
    if (tracks_per_batch == 0) {
        throw std::invalid_argument("tag_network: a batch holds at least one track");
    }
    OddProfile p;
    TagContext ctx(input, taxonomy, p);
    p = profile_head(input, taxonomy, ctx);
    sink.begin(p);
    SummaryBuilder summary(&taxonomy);
    const std::size_t tracks = input.map_input.geometry.fitted_tracks.edges.size();
    for (std::size_t first = 0; first < tracks; first += tracks_per_batch) {
        ctx.set_batch(first, std::min(tracks, first + tracks_per_batch));
        // Scenery from the geometry, then from the ways' tags and the features;
        // operational conditions and connectivity come with the way and structure tags.
        tag_horizontal(ctx);
        tag_vertical_and_cant(ctx);
        tag_track_count(ctx);
        tag_way_attributes(ctx);
        tag_features(ctx);
        tag_surroundings(ctx);
        tag_land_use(ctx);
        ctx.sort_elements();
        for (const auto& e : p.elements) {
            summary.add(e);
        }
        sink.add(p.elements);
        std::deque<TaggedElement>().swap(p.elements);
        ctx.end_batch();
    }
    // By OSM id, tag and value: the same list whatever the batches.
    std::stable_sort(p.unparsed.begin(), p.unparsed.end(), [](const Unparsed& a, const Unparsed& b) {
        return std::tie(a.osm_ids, a.tag, a.value) < std::tie(b.osm_ids, b.tag, b.value);
    });
    p.summary = summary.json(p);
    sink.end(p);
}

void WholeProfile::begin(const OddProfile& head) { out_ = head; }

void WholeProfile::add(std::deque<TaggedElement>& batch) {
    std::move(batch.begin(), batch.end(), std::back_inserter(out_.elements));
}

void WholeProfile::end(const OddProfile& tail) {
    out_.unparsed = tail.unparsed;
    out_.summary = tail.summary;
}

OddProfile tag_route(const TaggerInput& input, const Taxonomy& taxonomy) {
    OddProfile p;
    WholeProfile whole(p);
    tag_network(input, taxonomy, whole);
    return p;
}

namespace {

std::string user_data_text(const TaggedElement& t) {
    std::ostringstream v;
    v.precision(8);
    v << t.element_id << " s=" << t.s_start;
    if (!t.point) {
        v << '-' << t.s_end;
    }
    for (const auto& a : t.attributes) {
        v << ' ' << a.name << '=' << text_of(a.value);
    }
    return v.str();
}

} // namespace

void OddUserData::add(const TaggedElement& element) { by_road_[element.road_id].push_back(user_data_text(element)); }

std::vector<xodr::UserData> OddUserData::operator()(const xodr::Road& road) const {
    std::vector<xodr::UserData> out;
    const auto it = by_road_.find(road.id);
    if (it != by_road_.end()) {
        for (const std::string& text : it->second) {
            out.push_back({"odd", text});
        }
    }
    return out;
}

} // namespace railodd::odd
