#pragma once
// Checking a route's ODD profile against a declared ODD (`railodd profile
// --odd-spec`, docs/odd.md "Checking a route against an ODD spec").
//
// Matching: a spec entry covers its element and every element below it, and
// all entries on a tagged element's ancestry apply (an entry for "Scenery/
// Structures" with allowed: false puts tunnels and bridges outside; radius
// limits on ".../Curve" and a height limit on an ancestor both hold). This
// mirrors attribute inheritance in the taxonomy.
// A tagged element is outside the ODD when
//   - an entry on its ancestry has allowed: false,
//   - one of its attribute values is not admitted by a constraint of such an
//     entry (admits_number / admits_value / admits_flag), or
//   - the spec says unlisted_elements: outside and no entry covers it.
// A constraint on an attribute the element does not carry (or carries with a
// value of another type) cannot be judged from the map: it is counted as
// "unknown", not as a violation, because the map data rarely says everything
// (a crossing without a lights tag). Unknowns are listed per spec entry.
#include "railodd/odd/odd_spec.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/odd/taxonomy.hpp"

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace railodd::odd {

// A tagged element the spec rejects, at the element's place.
struct SpecViolation : MapPlace {
    std::string element;      // the tagged element's path
    std::string spec_element; // the spec entry that rejects it ("" for unlisted)
    std::string attribute;    // "" when the element itself is outside
    std::string value;        // the attribute value as text
    std::string unit;         // the taxonomy's unit of the attribute
    std::string constraint;   // "radius >= 300 m", "not allowed", "not listed (unlisted_elements: outside)"
    std::string note;         // the spec entry's note
    int spec_line = 0; // line of the constraint (or the entry) in the spec file
};

// Per spec entry, in spec order.
struct SpecEntryCount {
    std::string path;
    int line = 0;
    std::size_t matched = 0;  // tagged elements the entry applies to
    std::size_t outside = 0;  // of those, rejected by this entry
    std::size_t unknown = 0;  // of those, with a constrained attribute missing
    std::vector<std::string> unknown_attributes; // constrained attributes found missing, sorted
};

// A stretch of one track whose consecutive (touching or overlapping) elements
// are outside the ODD; points inside or at the ends of a stretch join it.
struct OutsideStretch {
    std::size_t track = 0;
    double chainage_start = 0.0;
    double chainage_end = 0.0;
    std::vector<std::string> road_ids; // in chainage order, each once
    std::vector<std::string> elements; // rejected element paths, sorted
    std::size_t violations = 0;
};

struct SpecVerdict {
    std::string spec_name;
    std::string spec_source;
    bool passed = true;
    std::size_t elements_checked = 0;
    std::size_t elements_outside = 0;
    std::size_t elements_unlisted = 0; // covered by no entry (inside or outside per the spec)
    std::vector<SpecViolation> violations; // by profile element order, then spec order
    std::vector<SpecEntryCount> entries;
    std::vector<OutsideStretch> stretches; // by track, then chainage
};

SpecVerdict check_spec(const OddProfile& profile, const OddSpec& spec, const Taxonomy& taxonomy);

// "IN ODD" / "OUTSIDE ODD", counts, the first `max_violations` violations with
// chainage and OSM ids, then "... N more", the stretches outside and unknowns.
std::string verdict_text(const SpecVerdict& verdict, std::size_t max_violations = 30);
nlohmann::ordered_json verdict_json(const SpecVerdict& verdict);

} // namespace railodd::odd
