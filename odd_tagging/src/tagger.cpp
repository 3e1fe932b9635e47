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

// Collects the batches into one profile (tag_route).
class WholeProfile : public ProfileSink {
public:
    explicit WholeProfile(OddProfile& out) : out_(out) {}
    void begin(const OddProfile& head) override { out_ = head; }
    void add(std::deque<TaggedElement>& batch) override {
        std::move(batch.begin(), batch.end(), std::back_inserter(out_.elements));
    }
    void end(const OddProfile& tail) override {
        out_.unparsed = tail.unparsed;
        out_.summary = tail.summary;
    }

private:
    OddProfile& out_;
};

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

OddUserData::OddUserData(const OddProfile& profile) : profile_(profile) {
    for (std::size_t i = 0; i < profile.elements.size(); ++i) {
        by_road_[profile.elements[i].road_id].push_back(i);
    }
}

std::vector<xodr::UserData> OddUserData::operator()(const xodr::Road& road) const {
    std::vector<xodr::UserData> out;
    const auto it = by_road_.find(road.id);
    if (it != by_road_.end()) {
        for (std::size_t i : it->second) {
            out.push_back({"odd", user_data_text(profile_.elements[i])});
        }
    }
    return out;
}

void add_odd_user_data(const OddProfile& profile, xodr::Map& map) {
    const OddUserData odd(profile);
    for (auto& r : map.roads) {
        for (auto& u : odd(r)) {
            r.user_data.push_back(std::move(u));
        }
    }
}

} // namespace railodd::odd
