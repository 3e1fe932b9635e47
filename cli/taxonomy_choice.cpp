#include "taxonomy_choice.hpp"

namespace railodd::cli {

namespace fs = std::filesystem;

std::optional<fs::path> taxonomy_file(const std::string& option, bool spec_given, const odd::OddProfile& profile,
                                      const fs::path& profile_path) {
    if (!option.empty()) {
        return fs::path{option};
    }
    if (!profile.taxonomy_file.empty()) {
        const fs::path named{profile.taxonomy_file};
        if (fs::is_regular_file(named)) {
            return named;
        }
        if (named.is_relative() && fs::is_regular_file(profile_path.parent_path() / named)) {
            return profile_path.parent_path() / named;
        }
    }
    const fs::path shipped = fs::path{RAILODD_DATA_DIR} / "odd" / "railway_odd.yaml";
    if (fs::is_regular_file(shipped) || spec_given) {
        return shipped; // with a spec, a missing taxonomy is reported by load_taxonomy
    }
    return std::nullopt;
}

} // namespace railodd::cli
