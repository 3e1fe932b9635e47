#pragma once
// odd_profile.json, .geojson and .csv written while the network is tagged
// (a ProfileSink for tag_network): each batch's elements are printed and
// dropped, so no profile is held whole. The one writer of the three files:
// a whole profile goes in as one batch. odd_profile.json is byte for byte
// what write_json gives for the whole profile.
//
// odd_profile.geojson: an RFC 7946 FeatureCollection in WGS84 lon/lat (7
// decimals, about 1 cm), one feature per line: a Point for point elements, a
// LineString for s-ranges, both from `lonlat` (a range with a single position
// becomes a Point, none a null geometry). Properties: odd_element,
// element_id, attributes (object), road_id, track, s_start, s_end,
// chainage_start, chainage_end, osm_ids, source.
//
// odd_profile.csv: RFC 4180 with a header row and CRLF line ends:
// odd_element, element_id, road_id, s_start, s_end, chainage_start,
// chainage_end (metres, 3 decimals), track, point, attributes
// ("name=value;name=value"), osm_ids (space separated), source. Fields
// holding a comma, quote or line break are quoted.
#include "railodd/odd/profile.hpp"

#include <filesystem>
#include <fstream>
#include <iosfwd>
#include <memory>
#include <string>

namespace railodd::odd {

namespace profile_elements {
class KindIndex;
}

class ProfileFiles final : public ProfileSink {
public:
    // odd_profile.json's rows wait in `scratch` (a file of the caller's,
    // overwritten, removed at end()): the kinds they index, in order of
    // first use, come before them in the file.
    ProfileFiles(std::ostream& json, std::ostream& geojson, std::ostream& csv, std::filesystem::path scratch);
    ~ProfileFiles() override;

    void begin(const OddProfile& head) override;
    void add(std::deque<TaggedElement>& batch) override;
    void end(const OddProfile& tail) override;

private:
    std::ostream& json_;
    std::ostream& geojson_;
    std::ostream& csv_;
    std::filesystem::path scratch_path_;
    std::ofstream rows_;
    OddProfile head_;
    std::unique_ptr<profile_elements::KindIndex> kinds_;
    std::size_t elements_ = 0;
    std::string line_, field_;
};

} // namespace railodd::odd
