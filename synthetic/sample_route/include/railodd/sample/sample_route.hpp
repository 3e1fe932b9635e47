#pragma once
// The embedded sample route: a fictional single-track line near lon 10.2,
// lat 48.3, designed as an exact alignment and drawn as OSM the way mappers
// draw it. It is both the README's demo input and the ground-truth fixture
// against which fitted geometry and ODD tags are checked.
#include <filesystem>

namespace railodd::sample {

struct SampleFiles {
    std::filesystem::path osm;   // sample_route.osm (OSM XML 0.6)
    std::filesystem::path dem;   // sample_route_dem.tif (EPSG:4326, Float32, 1 arc-second)
    std::filesystem::path truth; // sample_route_truth.json (design, clean positions)
};

// Writes the three files into dir (created if needed). Byte-identical on every
// run. Files are staged and renamed into place, so a failure leaves none of
// them half-written; throws railodd::OutputError naming the file.
SampleFiles write_sample_route(const std::filesystem::path& dir);

} // namespace railodd::sample
