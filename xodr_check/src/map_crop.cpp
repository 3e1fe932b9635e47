// The map cut to a selection of its roads (map_crop.hpp).
#include "railodd/xodr_check/map_crop.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/xodr_check/map_lines.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace railodd::xodr_check {

namespace {

constexpr double sample_step_m = 5.0;

using Samples = std::vector<std::pair<double, double>>;

// Points along a road's reference line, every sample_step_m and at its ends.
Samples sample_road(const MapRoad& r) {
    Samples out;
    const auto n = static_cast<std::size_t>(std::ceil(r.length / sample_step_m));
    for (std::size_t i = 0; i <= n; ++i) {
        const Pose p = r.pose(std::min(r.length, static_cast<double>(i) * sample_step_m));
        out.push_back({p.x, p.y});
    }
    return out;
}

// The chosen roads' samples in cells of the corridor's width: a road is near
// where one of its samples has a chosen sample within the corridor.
class Corridor {
public:
    Corridor(double width) : w_(std::max(width, 1.0)) {}
    void add(double x, double y) { cells_[key(cell(x), cell(y))].push_back({x, y}); }
    bool near(double x, double y, double d) const {
        const std::int64_t cx = cell(x), cy = cell(y);
        for (std::int64_t i = cx - 1; i <= cx + 1; ++i) {
            for (std::int64_t j = cy - 1; j <= cy + 1; ++j) {
                const auto it = cells_.find(key(i, j));
                if (it == cells_.end()) {
                    continue;
                }
                for (const auto& [px, py] : it->second) {
                    if (std::hypot(px - x, py - y) <= d) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

private:
    std::int64_t cell(double v) const { return static_cast<std::int64_t>(std::floor(v / w_)); }
    static std::uint64_t key(std::int64_t i, std::int64_t j) {
        return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint64_t>(j & 0xffffffff);
    }
    double w_;
    std::unordered_map<std::uint64_t, std::vector<std::pair<double, double>>> cells_;
};

bool in_box(const Samples& s, const CropSpec::Box& b) {
    return std::any_of(s.begin(), s.end(), [&](const auto& p) {
        return p.first >= b.xmin && p.first <= b.xmax && p.second >= b.ymin && p.second <= b.ymax;
    });
}

// The roads the spec names or boxes, and those within its corridor (`ids`
// and `samples` per road, in document order).
std::set<std::string> chosen_roads(const std::filesystem::path& file, const std::vector<std::string>& ids,
                                   const std::vector<Samples>& samples, const CropSpec& spec) {
    std::set<std::string> chosen;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        if (spec.box && in_box(samples[k], *spec.box)) {
            chosen.insert(ids[k]);
        }
    }
    for (const std::string& id : spec.roads) {
        if (std::find(ids.begin(), ids.end(), id) == ids.end()) {
            throw InputError(file.string(), "road " + id + " is not in the map");
        }
        chosen.insert(id);
    }
    if (spec.corridor_m > 0.0) {
        Corridor c(spec.corridor_m);
        for (std::size_t k = 0; k < ids.size(); ++k) {
            if (chosen.count(ids[k])) {
                for (const auto& [x, y] : samples[k]) {
                    c.add(x, y);
                }
            }
        }
        std::set<std::string> near = chosen;
        for (std::size_t k = 0; k < ids.size(); ++k) {
            const Samples& s = samples[k];
            if (std::any_of(s.begin(), s.end(), [&](const auto& p) { return c.near(p.first, p.second, spec.corridor_m); })) {
                near.insert(ids[k]);
            }
        }
        chosen = std::move(near);
    }
    return chosen;
}

// The road a connecting road's link end names ("" where none, or a junction).
std::string linked_road(const pugi::xml_node& road, const char* end) {
    const pugi::xml_node l = road.child("link").child(end);
    return std::string(l.attribute("elementType").as_string()) == "road" ? l.attribute("elementId").as_string() : "";
}

// Connecting roads whose both ends' roads are kept join the kept set.
void keep_connecting_roads(const pugi::xml_node& root, std::set<std::string>& keep) {
    for (const pugi::xml_node road : root.children("road")) {
        if (std::string(road.attribute("junction").as_string("-1")) == "-1") {
            continue;
        }
        const std::string a = linked_road(road, "predecessor"), b = linked_road(road, "successor");
        if (!a.empty() && !b.empty() && keep.count(a) && keep.count(b)) {
            keep.insert(road.attribute("id").as_string());
        }
    }
}

template <typename Pred>
std::size_t remove_children(pugi::xml_node parent, const char* name, Pred gone) {
    std::vector<pugi::xml_node> doomed;
    for (const pugi::xml_node n : parent.children(name)) {
        if (gone(n)) {
            doomed.push_back(n);
        }
    }
    for (const pugi::xml_node n : doomed) {
        parent.remove_child(n);
    }
    return doomed.size();
}

// Junctions lose the connections whose roads are gone, and go where none is
// left; the ids of those kept.
std::set<std::string> prune_junctions(pugi::xml_node root, const std::set<std::string>& roads, CropResult& r) {
    std::set<std::string> kept;
    for (pugi::xml_node j : root.children("junction")) {
        r.connections_dropped += remove_children(j, "connection", [&](const pugi::xml_node& c) {
            return !roads.count(c.attribute("incomingRoad").as_string()) ||
                   !roads.count(c.attribute("connectingRoad").as_string());
        });
    }
    remove_children(root, "junction", [&](const pugi::xml_node& j) { return !j.child("connection"); });
    for (const pugi::xml_node j : root.children("junction")) {
        kept.insert(j.attribute("id").as_string());
    }
    return kept;
}

// A kept road's links to removed roads or junctions dropped.
void prune_links(pugi::xml_node road, const std::set<std::string>& roads, const std::set<std::string>& junctions,
                 CropResult& r) {
    pugi::xml_node link = road.child("link");
    pugi::xml_node lanes = road.child("lanes");
    for (const char* end : {"predecessor", "successor"}) {
        const std::size_t dropped = remove_children(link, end, [&](const pugi::xml_node& l) {
            const std::string type = l.attribute("elementType").as_string(), id = l.attribute("elementId").as_string();
            return type == "junction" ? !junctions.count(id) : !roads.count(id);
        });
        r.links_dropped += dropped;
        if (dropped == 0) {
            continue;
        }
        // The lane links at that end name lanes of the road that is gone.
        pugi::xml_node section;
        for (const pugi::xml_node sec : lanes.children("laneSection")) {
            if (!section || std::string(end) == "successor") {
                section = sec;
            }
        }
        for (const char* side : {"left", "center", "right"}) {
            for (pugi::xml_node lane : section.child(side).children("lane")) {
                remove_children(lane.child("link"), end, [](const pugi::xml_node&) { return true; });
            }
        }
    }
}

// The rail extensions' references to removed roads: a switch whose main or
// side track is gone (and partners naming it), platform segments on removed
// roads, platforms without segments and stations without platforms.
void prune_rail(pugi::xml_node root, const std::set<std::string>& roads) {
    std::set<std::string> switches;
    for (pugi::xml_node road : root.children("road")) {
        remove_children(road.child("railroad"), "switch", [&](const pugi::xml_node& sw) {
            return !roads.count(sw.child("mainTrack").attribute("id").as_string()) ||
                   !roads.count(sw.child("sideTrack").attribute("id").as_string());
        });
        for (const pugi::xml_node sw : road.child("railroad").children("switch")) {
            switches.insert(sw.attribute("id").as_string());
        }
    }
    for (pugi::xml_node road : root.children("road")) {
        for (pugi::xml_node sw : road.child("railroad").children("switch")) {
            remove_children(sw, "partner", [&](const pugi::xml_node& p) { return !switches.count(p.attribute("id").as_string()); });
        }
    }
    for (pugi::xml_node st : root.children("station")) {
        for (pugi::xml_node pf : st.children("platform")) {
            remove_children(pf, "segment", [&](const pugi::xml_node& g) { return !roads.count(g.attribute("roadId").as_string()); });
        }
        remove_children(st, "platform", [](const pugi::xml_node& pf) { return !pf.child("segment"); });
    }
    remove_children(root, "station", [](const pugi::xml_node& st) { return !st.child("platform"); });
}

// Signal references, object references and controller entries naming what
// went with the removed roads.
void prune_references(pugi::xml_node root) {
    std::set<std::string> signals, objects;
    for (const pugi::xml_node road : root.children("road")) {
        for (const pugi::xml_node s : road.child("signals").children("signal")) {
            signals.insert(s.attribute("id").as_string());
        }
        for (const pugi::xml_node o : road.child("objects").children("object")) {
            objects.insert(o.attribute("id").as_string());
        }
    }
    for (pugi::xml_node road : root.children("road")) {
        remove_children(road.child("signals"), "signalReference",
                        [&](const pugi::xml_node& s) { return !signals.count(s.attribute("id").as_string()); });
        remove_children(road.child("objects"), "objectReference",
                        [&](const pugi::xml_node& o) { return !objects.count(o.attribute("id").as_string()); });
    }
    for (pugi::xml_node c : root.children("controller")) {
        remove_children(c, "control", [&](const pugi::xml_node& k) { return !signals.count(k.attribute("signalId").as_string()); });
    }
    remove_children(root, "controller", [](const pugi::xml_node& c) { return !c.child("control"); });
    std::set<std::string> controllers;
    for (const pugi::xml_node c : root.children("controller")) {
        controllers.insert(c.attribute("id").as_string());
    }
    for (pugi::xml_node j : root.children("junction")) {
        remove_children(j, "controller", [&](const pugi::xml_node& c) { return !controllers.count(c.attribute("id").as_string()); });
    }
}

} // namespace

struct MapCrop::Map {
    std::filesystem::path file;
    std::string text; // parsed again per cut: pugixml parses faster than it copies a document
    std::vector<std::string> ids;  // of the roads, in document order
    std::vector<Samples> samples;  // per road
};

MapCrop::MapCrop(const std::filesystem::path& file) {
    auto m = std::make_unique<Map>();
    m->file = file;
    for (const MapRoad& r : read_map_lines(file).roads) {
        m->ids.push_back(r.id);
        m->samples.push_back(sample_road(r));
    }
    std::ifstream in(file, std::ios::binary);
    m->text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    pugi::xml_document probe;
    if (!in || !probe.load_buffer(m->text.data(), m->text.size())) {
        throw InputError(file.string(), "cannot be read as XML");
    }
    map_ = std::move(m);
}

MapCrop::~MapCrop() = default;

CropResult MapCrop::cut(const CropSpec& spec) const {
    std::set<std::string> keep = chosen_roads(map_->file, map_->ids, map_->samples, spec);
    pugi::xml_document doc;
    doc.load_buffer(map_->text.data(), map_->text.size());
    pugi::xml_node root = doc.child("OpenDRIVE");
    keep_connecting_roads(root, keep);
    CropResult r;
    r.roads_in = map_->ids.size();
    remove_children(root, "road", [&](const pugi::xml_node& road) { return !keep.count(road.attribute("id").as_string()); });
    const std::set<std::string> junctions = prune_junctions(root, keep, r);
    for (pugi::xml_node road : root.children("road")) {
        prune_links(road, keep, junctions, r);
        ++r.roads_kept;
    }
    prune_rail(root, keep);
    prune_references(root);
    if (r.roads_kept == 0) {
        throw InputError(map_->file.string(), "the selection keeps no road of the map");
    }
    r.junctions_kept = junctions.size();
    std::ostringstream os;
    doc.save(os, "  ", pugi::format_default, pugi::encoding_utf8);
    r.xml = os.str();
    return r;
}

CropResult crop_map(const std::filesystem::path& file, const CropSpec& spec) { return MapCrop(file).cut(spec); }

} // namespace railodd::xodr_check
