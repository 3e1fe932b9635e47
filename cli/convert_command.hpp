#pragma once
// railodd convert INPUT -o OUTDIR: the convert pipeline (railodd::convert) on
// one route, its options the table's (railodd/convert/options.hpp).
#include "command.hpp"

#include "railodd/convert/options.hpp"

namespace railodd::cli {

class ConvertCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    convert::Options opt_;
};

} // namespace railodd::cli
