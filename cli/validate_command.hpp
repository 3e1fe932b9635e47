#pragma once
// railodd validate FILE.xodr: the independent OpenDRIVE checks (railodd::xodr_check),
// optionally XSD validation and a SUMO netconvert import; exit 5 when any fails.
#include "command.hpp"

#include <cstddef>
#include <string>

namespace railodd::cli {

struct ValidateOptions {
    std::string file;
    std::string xsd_dir;   // empty: no schema validation
    bool netconvert = false;
    bool json = false;
    std::size_t max_findings = 20; // findings listed in the text verdict
};

class ValidateCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    void setup() override;
    int run() override;

private:
    ValidateOptions opt_;
};

} // namespace railodd::cli
