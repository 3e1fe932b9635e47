#pragma once
// What a route contains, in numbers: km per curve radius, gradient and speed
// class, counts of crossings, stations, structures, switches and signals
// (docs/odd.md "Profile outputs"). The tagger stores summarize() as the
// profile's `summary`; `railodd profile` prints it with summary_text().
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

namespace railodd::odd {

// The `summary` object of odd_profile.json:
//   {"length_km", "tracks", "elements",
//    "curve_km_by_radius": {CLASS: km}, "gradient_km_by_class": {CLASS: km},
//    "speed_km_by_class": {CLASS: km},              // taxonomy bin order, every class listed
//    "landuse_km_by_kind": {KIND: km},              // taxonomy value order, every kind listed
//    "level_crossings_by_barrier": {VALUE: n}, "stations", "halts", "platforms",
//    "tunnels": {"count", "length_km"}, "bridges": {"count", "length_km"},
//    "switches", "signals_by_category": {CATEGORY: n}, "unparsed_values"}
// km are sums of (s_end - s_start) over the elements of a class. Elements are
// recognised by taxonomy id or path (ids are the stable key). Classes come from
// the taxonomy's bins; without a taxonomy every value is "unclassified", and a
// value outside all bins too. Elements lacking the attribute count as "unknown";
// speed limits without a number count under "kind: signals" / "kind: none".
nlohmann::ordered_json summarize(const OddProfile& profile, const Taxonomy* taxonomy);

// The same, element by element, for a profile that is never whole (a network
// tagged a batch of tracks at a time): add() every element in profile order,
// then json() with the profile's head (length_m, tracks, unparsed).
class SummaryBuilder {
public:
    explicit SummaryBuilder(const Taxonomy* taxonomy);
    SummaryBuilder(const SummaryBuilder&) = delete;
    SummaryBuilder& operator=(const SummaryBuilder&) = delete;
    ~SummaryBuilder();
    void add(const TaggedElement& e);
    nlohmann::ordered_json json(const OddProfile& head) const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

// The summary as aligned text (km with 2 decimals). Keys present in the
// profile's own `summary` are shown as stored; missing ones are computed from
// the elements with summarize(profile, taxonomy).
std::string summary_text(const OddProfile& profile, const Taxonomy* taxonomy);

} // namespace railodd::odd
