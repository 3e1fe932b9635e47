#pragma once
// railodd scenarios --map MAPDIR -o SCENDIR: concrete, route-anchored
// OpenSCENARIO scenarios from base-scenario templates and an asset catalog,
// with a traceability manifest and ODD coverage (docs/scenarios.md).
// Exit codes: 0 written, 1 usage, 2 unreadable or invalid input, 3 output.
#include "command.hpp"

#include "railodd/scenario/target.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace railodd::cli {

struct ScenariosOptions {
    std::string map_dir;
    std::string out_dir;
    std::string templates; // empty: data/scenario/templates.yaml
    std::string catalog;   // empty: data/scenario/assets.yaml
    std::string taxonomy;  // empty: data/odd/railway_odd.yaml
    std::string odd_spec;  // empty: coverage of the route only
    std::string strategy = "cover";
    std::size_t count = 0;
    std::uint64_t seed = 1;
    std::size_t max_anchors = 0;
    std::string osc_version;      // empty: the target's (1.2 for esmini, 1.0 for carla)
    std::string target = "esmini"; // esmini or carla (ScenarioRunner)
    bool quiet = false;
    double map_corridor_m = -1.0; // < 0: 200 m for maps over 5 MB, else the whole map (scenario_maps.hpp)
};

class ScenariosCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    ScenariosOptions opt_;
    int osc_minor_ = 2;
    scenario::Target target_ = scenario::Target::esmini;
};

} // namespace railodd::cli
