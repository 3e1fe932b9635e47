#pragma once
// odd_profile.json, .geojson and .csv written while the network is tagged
// (a ProfileSink for tag_network): each batch's elements are printed and
// dropped, so no profile is held whole. The files are byte for byte those
// write_json, write_geojson and write_csv give for the whole profile.
#include "railodd/odd/profile.hpp"

#include <filesystem>
#include <fstream>
#include <iosfwd>
#include <memory>
#include <string>

namespace railodd::odd {

namespace profile_elements {
class KindIndex;
}

class ProfileFiles final : public ProfileSink {
public:
    // odd_profile.json's rows wait in `scratch` (a file of the caller's,
    // overwritten, removed at end()): the kinds they index, in order of
    // first use, come before them in the file.
    ProfileFiles(std::ostream& json, std::ostream& geojson, std::ostream& csv, std::filesystem::path scratch);
    ~ProfileFiles() override;

    void begin(const OddProfile& head) override;
    void add(std::deque<TaggedElement>& batch) override;
    void end(const OddProfile& tail) override;

private:
    std::ostream& json_;
    std::ostream& geojson_;
    std::ostream& csv_;
    std::filesystem::path scratch_path_;
    std::ofstream rows_;
    OddProfile head_;
    std::unique_ptr<profile_elements::KindIndex> kinds_;
    std::size_t elements_ = 0;
    std::string line_, field_;
};

} // namespace railodd::odd
