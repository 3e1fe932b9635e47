#pragma once
// Locations of a known set of node ids, held as one sorted vector: memory grows
// with the selected objects, never with the input file (no full node index).
#include "railodd/ingest/projection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace railodd::ingest {

class NodeLocations {
public:
    struct Entry {
        std::int64_t id = 0;
        LonLat lonlat;
        double ele = std::numeric_limits<double>::quiet_NaN();
        bool present = false;
    };

    void want(std::int64_t id) { entries_.push_back({id, {}, std::numeric_limits<double>::quiet_NaN(), false}); }
    template <typename Range>
    void want_all(const Range& ids) {
        for (std::int64_t id : ids) {
            want(id);
        }
    }

    // Call once after all want()s and before any set() / find(). Stable: of
    // an id added twice (a file with duplicate node ids), the first stays.
    void seal() {
        std::stable_sort(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.id < b.id; });
        entries_.erase(std::unique(entries_.begin(), entries_.end(),
                                   [](const Entry& a, const Entry& b) { return a.id == b.id; }),
                       entries_.end());
    }

    Entry* find(std::int64_t id) {
        auto it = std::lower_bound(entries_.begin(), entries_.end(), id,
                                   [](const Entry& e, std::int64_t v) { return e.id < v; });
        return (it != entries_.end() && it->id == id) ? &*it : nullptr;
    }
    const Entry* find(std::int64_t id) const { return const_cast<NodeLocations*>(this)->find(id); }

    // A location known for `id`, or nullptr.
    const Entry* located(std::int64_t id) const {
        const Entry* e = find(id);
        return (e && e->present) ? e : nullptr;
    }

    // Adds an entry that is already located (for sets built while scanning).
    void add_located(std::int64_t id, LonLat ll) { entries_.push_back({id, ll, std::numeric_limits<double>::quiet_NaN(), true}); }

    std::size_t size() const noexcept { return entries_.size(); }
    const std::vector<Entry>& entries() const noexcept { return entries_; }

private:
    std::vector<Entry> entries_;
};

} // namespace railodd::ingest
