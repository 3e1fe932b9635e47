#include "validate_command.hpp"
#include "option_checks.hpp"

#include "railodd/util/errors.hpp"
#include "railodd/util/output_stage.hpp"
#include "railodd/xodr_check/check.hpp"

#include <filesystem>
#include <iostream>
#include <optional>

namespace railodd::cli {

namespace fs = std::filesystem;

CLI::App* ValidateCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand(
        "validate", "Check an OpenDRIVE file: geometry continuity, links, junctions, rail extensions (docs/validate.md)");
    app->add_option("FILE", opt_.file, "OpenDRIVE 1.6 / 1.7 / 1.8 file (.xodr)")->required();
    app->add_option("--xsd-dir", opt_.xsd_dir,
                    "Also validate against the ASAM XSD found in DIR (xmllint for 1.6/1.7, python3-xmlschema for 1.8)");
    app->add_flag("--netconvert", opt_.netconvert,
                  "Also import the file with SUMO netconvert; report its errors and rail/tram edges");
    app->add_flag("--json", opt_.json, "Print the verdict as JSON");
    app->add_option("--max-findings", opt_.max_findings, "Findings listed in the text verdict")->capture_default_str()->check(unsigned_integer);
    return app;
}

void ValidateCommand::setup() {
    // A wrong --xsd-dir is the user's mistake (exit 1); a missing FILE is bad input (exit 2).
    if (!opt_.xsd_dir.empty() && !fs::is_directory(opt_.xsd_dir)) {
        throw UsageError(opt_.xsd_dir, "--xsd-dir is not a directory");
    }
}

int ValidateCommand::run() {
    finish_pending_commit(fs::absolute(opt_.file).parent_path());
    xodr_check::Verdict verdict;
    const xodr_check::CheckResult checks = xodr_check::check_file(opt_.file, verdict.limits);
    verdict.checks = &checks;
    std::optional<xodr_check::SchemaResult> schema;
    if (!opt_.xsd_dir.empty()) {
        schema = xodr_check::validate_schema(opt_.file, checks.summary.version, opt_.xsd_dir);
        verdict.schema = &*schema;
    }
    std::optional<xodr_check::NetconvertResult> net;
    if (opt_.netconvert) {
        net = xodr_check::run_netconvert(opt_.file);
        verdict.netconvert = &*net;
    }
    std::cout << (opt_.json ? xodr_check::verdict_json(verdict) : xodr_check::verdict_text(verdict, opt_.max_findings));
    return verdict.passed() ? exit_ok : exit_invalid;
}

} // namespace railodd::cli
