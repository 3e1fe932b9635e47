#pragma once
// Where each actor's target is on the map, in world coordinates: the play
// checks compare the recorded end position with it, whichever of two
// overlapping roads the player reports the actor on (a crossing road cut
// back beside the track, a parallel road).
#include "railodd/xodr_check/map_lines.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <string>

namespace railodd::cli {

class TargetPlaces {
public:
    // Reads every map the manifest's scenarios name (their `map`, relative
    // to `dir`), once each. A map that cannot be read leaves its targets
    // unplaced: the checks then compare road and s as the player reports them.
    TargetPlaces(const nlohmann::ordered_json& manifest, const std::filesystem::path& dir);

    // Each actor target of `scenario` (its manifest entry) gains "x" and
    // "y" where its road and lane are on the scenario's map.
    void place(nlohmann::json& scenario) const;

private:
    using Roads = std::map<std::string, xodr_check::MapRoad>;
    std::map<std::string, Roads> maps_; // by the manifest's map name
};

} // namespace railodd::cli
