#include "osm_passes.hpp"

#include "osm_scan.hpp"
#include "tag_rules.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <optional>

namespace railodd::ingest {

namespace {

using bits = osmium::osm_entity_bits::type;

std::vector<std::int64_t> refs_of(const osmium::Way& way) {
    std::vector<std::int64_t> refs;
    refs.reserve(way.nodes().size());
    for (const auto& nr : way.nodes()) {
        refs.push_back(nr.ref());
    }
    return refs;
}

RawWay raw_way(const osmium::Way& way) {
    RawWay r{way.id(), {}, refs_of(way)};
    r.tags = tags_of(way.tags(), r.text_repaired);
    return r;
}


double ele_of(const osmium::TagList& tags) {
    const char* v = tags.get_value_by_key("ele");
    if (!v) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    char* end = nullptr;
    const double e = std::strtod(v, &end);
    // "inf", "1e999" or a value no terrain has is no elevation (as the DEM's voids).
    return end != v && e >= -1000.0 && e <= 10000.0 ? e : std::numeric_limits<double>::quiet_NaN();
}

// A closed way with a land-use kind, or a member of a land-use multipolygon.
std::optional<RawLandUseWay> land_use_way(const osmium::Way& way, const std::vector<std::int64_t>& members) {
    const auto& nodes = way.nodes();
    const bool closed = nodes.size() >= 4 && nodes.front().ref() == nodes.back().ref();
    auto lu = closed ? land_use_kind(way.tags()) : std::nullopt;
    if (!lu && !std::binary_search(members.begin(), members.end(), way.id())) {
        return std::nullopt;
    }
    RawLandUseWay r{{way.id(), {}, refs_of(way)}, {}, {}};
    if (lu) {
        r.kind = std::move(lu->kind);
        r.tag = std::move(lu->tag);
    }
    return r;
}

} // namespace

WayScan scan_track_ways(const std::filesystem::path& file, const std::vector<std::int64_t>* members,
                        std::size_t road_refs_cap, const LandUseWanted& land_use,
                        const std::vector<std::int64_t>* near) {
    auto touches = [&](const osmium::Way& way) {
        return !near || std::any_of(way.nodes().begin(), way.nodes().end(), [&](const osmium::NodeRef& nr) {
                   return std::binary_search(near->begin(), near->end(), nr.ref());
               });
    };
    WayScan scan;
    scan.roads_complete = road_refs_cap > 0;
    scan.land_use_complete = land_use.refs_cap > 0;
    std::size_t road_refs = 0, land_use_refs = 0;
    scan_osm(file, bits::way, "reading ways", [&](const osmium::OSMObject& obj) {
        const auto& way = static_cast<const osmium::Way&>(obj);
        if (is_track(way.tags())) {
            if ((!members || std::binary_search(members->begin(), members->end(), way.id())) && touches(way)) {
                scan.tracks.push_back(raw_way(way));
            }
        } else if (auto kind = area_feature_kind(way.tags()); kind && touches(way)) {
            RawFeature f;
            f.osm_type = "way";
            f.id = way.id();
            f.kind = std::move(*kind);
            f.tags = tags_of(way.tags(), f.text_repaired);
            f.refs = refs_of(way);
            scan.area_features.push_back(std::move(f));
        }
        if (scan.roads_complete && is_road(way.tags())) {
            road_refs += way.nodes().size();
            if (road_refs > road_refs_cap) {
                scan.roads_complete = false; // too many: the corridor passes read them instead
                std::vector<RawWay>().swap(scan.roads);
            } else {
                scan.roads.push_back(raw_way(way));
            }
        }
        if (scan.land_use_complete) {
            if (auto lu = land_use_way(way, land_use.members)) {
                land_use_refs += lu->way.refs.size();
                if (land_use_refs > land_use.refs_cap) {
                    scan.land_use_complete = false; // read around the tracks once they are known
                    std::vector<RawLandUseWay>().swap(scan.land_use);
                } else {
                    scan.land_use.push_back(std::move(*lu));
                }
            }
        }
    });
    return scan;
}

std::vector<RawLandUseWay> scan_land_use_ways(const std::filesystem::path& file,
                                              const std::vector<std::int64_t>& members, const NodeLocations& near) {
    std::vector<RawLandUseWay> out;
    scan_osm(file, bits::way, "reading land use", [&](const osmium::OSMObject& obj) {
        const auto& way = static_cast<const osmium::Way&>(obj);
        const bool touches = std::any_of(way.nodes().begin(), way.nodes().end(),
                                         [&](const osmium::NodeRef& nr) { return near.located(nr.ref()); });
        if (touches) {
            if (auto lu = land_use_way(way, members)) {
                out.push_back(std::move(*lu));
            }
        }
    });
    return out;
}

std::vector<std::int64_t> node_ids_in(const std::filesystem::path& file, const BBox& box) {
    std::vector<std::int64_t> ids;
    scan_osm(file, bits::node, "reading nodes in the selection", [&](const osmium::OSMObject& obj) {
        const auto& node = static_cast<const osmium::Node&>(obj);
        if (node.location().valid() && box.contains({node.location().lon(), node.location().lat()})) {
            ids.push_back(node.id());
        }
    });
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return ids;
}

NodeScan scan_nodes(const std::filesystem::path& file, NodeLocations& wanted, const BBox* feature_box) {
    NodeScan scan;
    scan_osm(file, bits::node, "reading nodes", [&](const osmium::OSMObject& obj) {
        const auto& node = static_cast<const osmium::Node&>(obj);
        ++scan.node_count;
        if (!node.location().valid()) {
            return; // deleted or location-less nodes count as missing
        }
        const LonLat ll{node.location().lon(), node.location().lat()};
        auto* e = wanted.find(node.id());
        if (e && e->present) {
            // A file with one node id twice: the first location is kept, the
            // conflict reported (osm_reader records it as a repair).
            if (e->lonlat.lon != ll.lon || e->lonlat.lat != ll.lat) {
                scan.duplicates.push_back({node.id(), ll});
            }
        } else if (e) {
            e->lonlat = ll;
            e->ele = ele_of(node.tags());
            e->present = true;
        }
        if (!e && feature_box && !feature_box->contains(ll)) {
            return; // off every way read, and far from the selection
        }
        if (auto kind = point_feature_kind(node.tags())) {
            RawFeature f;
            f.osm_type = "node";
            f.id = node.id();
            f.kind = std::move(*kind);
            f.tags = tags_of(node.tags(), f.text_repaired);
            f.lonlat = ll;
            scan.point_features.push_back(std::move(f));
        }
    });
    return scan;
}

void locate_nodes(const std::filesystem::path& file, NodeLocations& wanted, const std::string& pass) {
    scan_osm(file, bits::node, pass, [&](const osmium::OSMObject& obj) {
        const auto& node = static_cast<const osmium::Node&>(obj);
        if (auto* e = wanted.find(node.id()); e && !e->present && node.location().valid()) {
            e->lonlat = {node.location().lon(), node.location().lat()};
            e->present = true;
        }
    });
}

NodeLocations collect_nodes(const std::filesystem::path& file, const std::function<bool(LonLat)>& keep) {
    NodeLocations found;
    scan_osm(file, bits::node, "reading corridor nodes", [&](const osmium::OSMObject& obj) {
        const auto& node = static_cast<const osmium::Node&>(obj);
        if (!node.location().valid()) {
            return;
        }
        const LonLat ll{node.location().lon(), node.location().lat()};
        if (keep(ll)) {
            found.add_located(node.id(), ll);
        }
    });
    found.seal();
    return found;
}

std::vector<RawWay> scan_road_ways(const std::filesystem::path& file, const NodeLocations& corridor) {
    std::vector<RawWay> roads;
    scan_osm(file, bits::way, "reading roads", [&](const osmium::OSMObject& obj) {
        const auto& way = static_cast<const osmium::Way&>(obj);
        if (!is_road(way.tags())) {
            return;
        }
        const bool near = std::any_of(way.nodes().begin(), way.nodes().end(),
                                      [&](const osmium::NodeRef& nr) { return corridor.located(nr.ref()); });
        if (near) {
            roads.push_back(raw_way(way));
        }
    });
    return roads;
}

} // namespace railodd::ingest
