#include "profile_command.hpp"
#include "option_checks.hpp"
#include "taxonomy_choice.hpp"

#include "railodd/odd/odd_spec.hpp"
#include "railodd/odd/profile.hpp"
#include "railodd/odd/profile_summary.hpp"
#include "railodd/odd/spec_check.hpp"
#include "railodd/odd/taxonomy.hpp"
#include "railodd/util/errors.hpp"
#include "railodd/util/output_stage.hpp"

#include <filesystem>
#include <iostream>
#include <optional>

namespace railodd::cli {

namespace fs = std::filesystem;

namespace {

fs::path profile_file(const std::string& map_dir) {
    const fs::path p{map_dir};
    return fs::is_directory(p) ? p / "odd_profile.json" : p;
}

} // namespace

CLI::App* ProfileCommand::add(CLI::App& parent) {
    CLI::App* app = parent.add_subcommand(
        "profile", "Summarise a route's ODD profile and check it against a declared ODD (docs/odd.md)");
    app->add_option("MAPDIR", opt_.map_dir, "Output folder of `railodd convert` (or its odd_profile.json)")
        ->required();
    app->add_option("--odd-spec", opt_.odd_spec, "Declared ODD (YAML) to check the route against; exit 5 if outside");
    app->add_option("--taxonomy", opt_.taxonomy,
                    "Taxonomy file (default: the profile's, else data/odd/railway_odd.yaml)");
    app->add_flag("--json", opt_.json, "Print the summary and verdict as JSON");
    app->add_option("--max-violations", opt_.max_violations, "Violations listed in the text verdict")
        ->check(unsigned_integer)
        ->capture_default_str();
    return app;
}

int ProfileCommand::run() {
    const fs::path file = profile_file(opt_.map_dir);
    finish_pending_commit(file.parent_path().empty() ? fs::path{"."} : file.parent_path());
    const odd::OddProfile profile = odd::read_profile(file);
    std::optional<odd::Taxonomy> taxonomy;
    if (const auto tax_file = taxonomy_file(opt_.taxonomy, !opt_.odd_spec.empty(), profile, file)) {
        taxonomy = odd::load_taxonomy(*tax_file);
        if (!profile.taxonomy_version.empty() && profile.taxonomy_version != taxonomy->version) {
            std::cerr << "railodd: warning: " << file.string() << " was tagged with taxonomy version "
                      << profile.taxonomy_version << ", " << tax_file->string() << " is version "
                      << taxonomy->version << '\n';
        }
    }
    const odd::Taxonomy* tax = taxonomy ? &*taxonomy : nullptr;
    std::optional<odd::SpecVerdict> verdict;
    if (!opt_.odd_spec.empty()) {
        verdict = odd::check_spec(profile, odd::load_odd_spec(opt_.odd_spec, *taxonomy), *taxonomy);
    }
    if (opt_.json) {
        nlohmann::ordered_json j;
        j["profile"] = file.string();
        j["taxonomy"] = tax ? tax->source : "";
        nlohmann::ordered_json summary = odd::summarize(profile, tax);
        if (profile.summary.is_object()) {
            summary.update(profile.summary); // the stored numbers win, as in the text
        }
        j["summary"] = std::move(summary);
        j["odd_spec"] = verdict ? odd::verdict_json(*verdict) : nlohmann::ordered_json(nullptr);
        std::cout << j.dump(2) << '\n';
    } else {
        std::cout << "profile: " << file.string() << '\n' << odd::summary_text(profile, tax);
        if (verdict) {
            std::cout << '\n' << odd::verdict_text(*verdict, opt_.max_violations);
        }
    }
    return !verdict || verdict->passed ? exit_ok : exit_invalid;
}

} // namespace railodd::cli
