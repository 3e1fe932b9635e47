#pragma once
// railodd profile MAPDIR [--odd-spec SPEC.yaml]: the route's ODD profile
// (odd_profile.json written by `railodd convert`) as a summary and, with a
// spec, the verdict whether the route lies inside that ODD (docs/odd.md).
// Exit codes: 0 inside or no spec, 5 outside, 2 unreadable input, 1 usage.
#include "command.hpp"

#include <cstddef>
#include <string>

namespace railodd::cli {

struct ProfileOptions {
    std::string map_dir;  // a convert output folder, or the odd_profile.json itself
    std::string odd_spec; // empty: summary only
    std::string taxonomy; // empty: the profile's taxonomy file, else the shipped one
    bool json = false;
    std::size_t max_violations = 30;
};

class ProfileCommand : public Command {
public:
    CLI::App* add(CLI::App& parent) override;
    int run() override;

private:
    ProfileOptions opt_;
};

} // namespace railodd::cli
