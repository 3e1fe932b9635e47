#include "way_parts.hpp"

#include <algorithm>

namespace railodd::ingest {

namespace {

// Consecutive repeats of one node are a mapping slip, not geometry.
std::size_t remove_repeated_refs(std::vector<std::int64_t>& refs) {
    const std::size_t before = refs.size();
    refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
    return before - refs.size();
}

} // namespace

BuiltWay build_way(RawWay raw, const Locator& locate) {
    BuiltWay built;
    Way& way = built.way;
    way.origin = Origin::osm;
    way.id = raw.id;
    way.node_count = raw.refs.size();
    if (const std::size_t repeated = remove_repeated_refs(raw.refs); repeated > 0) {
        built.repairs.push_back("removed " + std::to_string(repeated) + " repeated consecutive node reference(s)");
    }
    std::vector<NodeRef> current;
    std::size_t single_node_parts = 0;
    auto close_part = [&] {
        if (current.size() >= 2) {
            way.parts.push_back(std::move(current));
        } else if (current.size() == 1) {
            ++single_node_parts;
        }
        current.clear();
    };
    for (std::int64_t ref : raw.refs) {
        if (const auto* e = locate(ref)) {
            NodeRef n;
            n.id = ref;
            n.lonlat = e->lonlat;
            n.ele = e->ele;
            current.push_back(n);
        } else {
            ++way.missing_nodes;
            close_part();
        }
    }
    close_part();
    way.tags = std::move(raw.tags);

    if (way.parts.empty() && raw.refs.size() < 2) {
        built.drop_reason = "way has only " + std::to_string(raw.refs.size()) + " distinct node(s)";
    } else if (way.parts.empty()) {
        built.drop_reason = way.missing_nodes == way.node_count
                                ? "none of its " + std::to_string(way.node_count) + " nodes is in the input"
                                : "fewer than two consecutive of its " + std::to_string(way.node_count) +
                                      " nodes are in the input (" + std::to_string(way.missing_nodes) + " missing)";
    } else if (way.missing_nodes > 0) {
        std::string action = "clipped: " + std::to_string(way.missing_nodes) + " of " +
                             std::to_string(way.node_count) + " nodes missing from the input; kept " +
                             std::to_string(way.parts.size()) + " contiguous part(s)";
        if (single_node_parts > 0) {
            action += ", discarded " + std::to_string(single_node_parts) + " isolated node(s)";
        }
        built.repairs.push_back(std::move(action));
    }
    return built;
}

void add_repairs(IngestResult& result, const char* kind, const BuiltWay& built) {
    for (const auto& a : built.repairs) {
        result.repairs.push_back({kind, "way", built.way.id, a});
    }
}

} // namespace railodd::ingest
