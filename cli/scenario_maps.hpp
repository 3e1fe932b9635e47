#pragma once
// Scenario maps cut to the corridor of their routes (issue 40): a player loads
// the map of every scenario it plays, and a city network's map takes a minute
// to load, while a scenario needs its route, the roads crossing it and what is
// in sight. Each distinct set of route roads gets one cut map
// (xodr_check::crop_map), shared by the scenarios that use it.
#include "railodd/scenario/generator.hpp"
#include "railodd/util/output_stage.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace railodd::cli {

// Maps larger than this are cut by default: up to it (Liechtenstein 4.1 MB,
// Krems 5.0 MB) a scenario loads and plays in 6-7 s in esmini.
constexpr std::uintmax_t corridor_default_above_bytes = 5'000'000;
constexpr double corridor_default_m = 200.0;

// The corridor to cut at: `requested` where given (>= 0; 0: whole map), else
// the default for the map's size.
double corridor_for(double requested, const std::filesystem::path& map);

// The map's junction connecting roads, what each links (routes through a
// switch take the one that leads where they go; GenerateOptions).
std::vector<scenario::ConnectingRoad> connecting_roads(const std::filesystem::path& map);

// Writes maps/corridor_N.xodr into the stage, one per distinct set of roads
// the scenarios run on (the ego's route, every actor's start, path and
// target), and points each scenario's LogicFile at its own.
void cut_scenario_maps(OutputStage& stage, const std::filesystem::path& map, double corridor_m,
                       scenario::Generation& generation);

} // namespace railodd::cli
