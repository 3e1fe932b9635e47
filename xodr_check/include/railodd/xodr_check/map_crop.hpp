#pragma once
// A map cut to part of itself: the roads a user names (a route) or that lie in
// a box, plus every road within a corridor of them, as a subset of the input
// document. Ids and s-coordinates are kept; links to removed roads and
// junctions are dropped, junctions lose the connections whose roads are gone
// (and are dropped when none is left), signal references and controller
// entries that name removed signals go with them. A connecting road is kept
// where the roads at both its ends are, so every movement between kept roads
// survives.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace railodd::xodr_check {

struct CropSpec {
    std::vector<std::string> roads; // road ids; each must exist
    struct Box {
        double xmin = 0, ymin = 0, xmax = 0, ymax = 0; // map coordinates (m)
    };
    std::optional<Box> box; // roads with a point inside
    double corridor_m = 0.0; // roads with a point this close to a chosen one
};

struct CropResult {
    std::string xml;            // the cut map
    std::size_t roads_kept = 0; // of roads_in
    std::size_t roads_in = 0;
    std::size_t junctions_kept = 0;
    std::size_t links_dropped = 0;       // road links to removed roads or junctions
    std::size_t connections_dropped = 0; // junction connections whose roads are gone
};

// A map read once and cut as often as asked (a scenario set cuts one map per
// distinct set of roads). Throws railodd::InputError naming the file for an
// unreadable map; cut() for an unknown road id or a selection that keeps no
// road.
class MapCrop {
public:
    explicit MapCrop(const std::filesystem::path& file);
    ~MapCrop();
    MapCrop(const MapCrop&) = delete;
    MapCrop& operator=(const MapCrop&) = delete;
    CropResult cut(const CropSpec& spec) const;

private:
    struct Map; // the parsed document and each road's samples (map_crop.cpp)
    std::unique_ptr<const Map> map_;
};

// MapCrop(file).cut(spec).
CropResult crop_map(const std::filesystem::path& file, const CropSpec& spec);

} // namespace railodd::xodr_check
