// railodd: OpenStreetMap / GIS railway data to simulation maps and scenarios.
#include "batch_command.hpp"
#include "command.hpp"
#include "convert_command.hpp"
#include "merge_command.hpp"
#include "play_command.hpp"
#include "profile_command.hpp"
#include "report_command.hpp"
#include "sample_command.hpp"
#include "scenarios_command.hpp"
#include "validate_command.hpp"
#include "crop_command.hpp"

#include "railodd/util/errors.hpp"

#include <iostream>
#include <memory>
#include <vector>

int main(int argc, char** argv) {
    using namespace railodd;
    CLI::App app{"railodd: real GIS railway data to simulation-ready OpenDRIVE maps and scenarios"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string{"railodd 0.1.0"});

    std::vector<std::unique_ptr<cli::Command>> commands;
    commands.push_back(std::make_unique<cli::BatchCommand>());
    commands.push_back(std::make_unique<cli::ConvertCommand>());
    commands.push_back(std::make_unique<cli::CropCommand>());
    commands.push_back(std::make_unique<cli::MergeCommand>());
    commands.push_back(std::make_unique<cli::PlayCommand>());
    commands.push_back(std::make_unique<cli::ProfileCommand>());
    commands.push_back(std::make_unique<cli::ReportCommand>());
    commands.push_back(std::make_unique<cli::SampleCommand>());
    commands.push_back(std::make_unique<cli::ScenariosCommand>());
    commands.push_back(std::make_unique<cli::ValidateCommand>());
    std::vector<CLI::App*> subs;
    for (auto& c : commands) {
        subs.push_back(c->add(app));
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? exit_ok : exit_usage;
    }

    try {
        for (std::size_t i = 0; i < commands.size(); ++i) {
            if (subs[i]->parsed()) {
                commands[i]->setup();
                return commands[i]->run();
            }
        }
    } catch (const Interrupted& e) {
        std::cerr << "railodd: " << e.what() << ": stopped, nothing written\n";
        return 128 + e.signal();
    } catch (const UsageError& e) {
        std::cerr << "railodd: error: " << e.what() << '\n';
        return exit_usage;
    } catch (const InputError& e) {
        std::cerr << "railodd: input error: " << e.what() << '\n';
        return exit_input;
    } catch (const OutputError& e) {
        std::cerr << "railodd: output error: " << e.what() << '\n';
        return exit_output;
    } catch (const std::exception& e) {
        std::cerr << "railodd: internal error: " << e.what() << '\n';
        return exit_internal;
    }
    return exit_usage;
}
