#pragma once
// The taxonomy a profile's classes and an ODD spec are read against:
// --taxonomy, else the file the profile was tagged with (as written, then
// beside the profile), else the shipped one. Without --taxonomy or a spec a
// missing file is no error (nullopt): what the profile stores is shown as is.
#include "railodd/odd/profile.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace railodd::cli {

std::optional<std::filesystem::path> taxonomy_file(const std::string& option, bool spec_given,
                                                   const odd::OddProfile& profile,
                                                   const std::filesystem::path& profile_path);

} // namespace railodd::cli
