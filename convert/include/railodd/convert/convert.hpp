#pragma once
// The convert pipeline as one call (docs/ARCHITECTURE.md): ingest, track
// graph and fit, vertical profiles, cant, topology, the OpenDRIVE map, the
// ODD profile and report.json / report.html, all staged and moved into
// options.outdir together. `railodd convert`, the fuzz harness, the tests and
// the benchmarks call it; `railodd batch` runs `railodd convert` per route.
#include "railodd/convert/options.hpp"
#include "railodd/ingest/types.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace railodd::convert {

struct Result {
    std::string source, selection; // as ingest described them
    ingest::IngestCounts counts;
    std::size_t ways_in_map = 0; // track ways with at least one stretch in map.xodr
    std::vector<std::filesystem::path> written;
};

// Checks the options (check()) and runs the conversion. Throws InputError,
// OutputError or UsageError with the file or option; nothing is left in
// options.outdir when it does.
Result run(const Options& options);

} // namespace railodd::convert
