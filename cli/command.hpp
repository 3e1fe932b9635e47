#pragma once
// One small class per subcommand (the osmium-tool pattern): add() declares the
// options on the CLI11 parser, setup() validates the parsed values, run() does
// the I/O and returns the exit code. Errors are thrown and caught once in main().
#include <CLI/CLI.hpp>

namespace railodd::cli {

class Command {
public:
    virtual ~Command() = default;
    virtual CLI::App* add(CLI::App& parent) = 0;
    virtual void setup() {}
    virtual int run() = 0;
};

} // namespace railodd::cli
