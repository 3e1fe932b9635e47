#pragma once
// Up-to-date check of `railodd batch`: OUTROOT/ID/.railodd-batch-stamp.json
// holds what a route's outputs were made from (the resolved route, a
// fingerprint of every file it reads, the railodd version and executable).
// A route whose stamp matches and whose outputs exist is skipped.
#include "batch_routes.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace railodd::cli {

inline constexpr const char* batch_stamp_name = ".railodd-batch-stamp.json";
inline constexpr const char* railodd_version = "0.1.0";

nlohmann::ordered_json make_stamp(const BatchRoute& route);

// True when `dir` holds a stamp equal to `stamp` and the route's outputs.
bool up_to_date(const std::filesystem::path& dir, const BatchRoute& route, const nlohmann::ordered_json& stamp);

// Written only after the route succeeded; removed before it runs, so an
// interrupted or failed run never looks up to date.
void write_stamp(const std::filesystem::path& dir, const nlohmann::ordered_json& stamp);
void remove_stamp(const std::filesystem::path& dir);

} // namespace railodd::cli
