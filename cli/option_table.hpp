#pragma once
// The convert options' table (railodd/convert/options.hpp) as CLI11 options:
// each row's flag, help, default and check, bound to its field.
#include "railodd/convert/options.hpp"

#include <CLI/CLI.hpp>

namespace railodd::cli {

void add_table_options(CLI::App& app, convert::Options& options);

} // namespace railodd::cli
