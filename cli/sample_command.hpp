#pragma once
// railodd sample -o DIR: write the embedded sample route (OSM, DEM and ground
// truth), the input of the README's walkthrough.
#include "command.hpp"

#include <string>

namespace railodd::cli {

class SampleCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    int run() override;

private:
    std::string outdir_;
};

} // namespace railodd::cli
