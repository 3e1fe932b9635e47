#pragma once
// railodd crop MAP.xodr -o OUT.xodr: the map cut to named roads (a route) or a
// box, plus every road within a corridor of them (xodr_check::crop_map).
#include "command.hpp"

#include <string>
#include <vector>

namespace railodd::cli {

struct CropOptions {
    std::string map;
    std::string out;
    std::vector<std::string> roads; // --roads ID,ID,...
    std::string box;                // --box XMIN,YMIN,XMAX,YMAX (map coordinates, m)
    double corridor_m = 0.0;
};

class CropCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    CropOptions opt_;
};

} // namespace railodd::cli
