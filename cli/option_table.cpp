#include "option_table.hpp"

#include <string>
#include <type_traits>

namespace railodd::cli {

namespace {

std::string names_of(const convert::OptionSpec& spec) {
    if (spec.positional) {
        std::string n{spec.key};
        for (char& c : n) {
            c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
        return n;
    }
    const std::string flag = convert::flag_of(spec);
    return spec.short_name.empty() ? flag : std::string{spec.short_name} + "," + flag;
}

// The row's check as a CLI11 validator, named as --help shows the value.
CLI::Validator validator(const convert::OptionSpec& spec) {
    std::string name;
    switch (spec.kind) {
    case convert::OptionKind::number:
        name = "FINITE in [" + CLI::detail::to_string(spec.lo) + " - " + CLI::detail::to_string(spec.hi) + "]";
        break;
    case convert::OptionKind::count: name = "UINT"; break;
    case convert::OptionKind::bbox: name = "W,S,E,N"; break;
    case convert::OptionKind::path:
    case convert::OptionKind::paths: name = "PATH"; break;
    default:
        for (const std::string_view c : spec.choices) {
            name += (name.empty() ? "{" : ",") + std::string{c};
        }
        name = !name.empty() ? name + "}" : std::string{spec.format};
    }
    return CLI::Validator([&spec](std::string& text) { return convert::check_value(spec, text); }, name);
}

} // namespace

void add_table_options(CLI::App& app, convert::Options& options) {
    for (const convert::OptionSpec& spec : convert::option_table()) {
        const std::string names = names_of(spec);
        const std::string help{spec.help};
        std::visit(
            [&](auto member) {
                auto& value = options.*member;
                if constexpr (std::is_same_v<std::remove_reference_t<decltype(value)>, bool>) {
                    app.add_flag(names, value, help);
                } else {
                    CLI::Option* opt = app.add_option(names, value, help)->check(validator(spec));
                    if (spec.required) {
                        opt->required();
                    }
                    if (spec.show_default) {
                        opt->capture_default_str();
                    }
                }
            },
            spec.field);
    }
}

} // namespace railodd::cli
