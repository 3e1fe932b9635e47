#pragma once
// Tags every stretch and point of track with the ODD elements of the taxonomy
// it belongs to (docs/odd.md, "Tagging"), from the fitted geometry, the OSM
// tags behind it and the OpenDRIVE map built from it, so that each tag names
// the road and s it applies to and the OSM ids it came from.
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/xodr/map_builder.hpp"

#include <cstddef>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace railodd::odd {

struct TaggerInput {
    const xodr::MapInput& map_input; // the geometry stage's results
    const xodr::MapBuild& map;       // where each track went in map.xodr
};

// Tags the network a batch of tracks (graph edges) at a time, handing each
// batch's elements, in order, to the sink: a national network's profile is
// never held whole. The profile does not depend on the batch size
// (`unparsed` is sorted by OSM ids, tag and value).
inline constexpr std::size_t default_tracks_per_batch = 256;
void tag_network(const TaggerInput& input, const Taxonomy& taxonomy, ProfileSink& sink,
                 std::size_t tracks_per_batch = default_tracks_per_batch);

// The same profile, whole.
OddProfile tag_route(const TaggerInput& input, const Taxonomy& taxonomy);

// A sink that collects the batches into one profile (tag_route; convert
// along a route, which is cut from the whole network's profile).
class WholeProfile final : public ProfileSink {
public:
    explicit WholeProfile(OddProfile& out) : out_(out) {}
    void begin(const OddProfile& head) override;
    void add(std::deque<TaggedElement>& batch) override;
    void end(const OddProfile& tail) override;

private:
    OddProfile& out_;
};

// The tags as <userData code="odd"> on the roads they belong to, one per
// element: "ID s=START-END name=value ...", in profile order. Fed element by
// element as the profile is made; handed to xodr::write_xodr as its extra
// user data, one road at a time. The entries' text only is kept, not the
// elements.
class OddUserData {
public:
    void add(const TaggedElement& element);
    std::vector<xodr::UserData> operator()(const xodr::Road& road) const;

private:
    std::map<std::string, std::vector<std::string>> by_road_;
};

} // namespace railodd::odd
