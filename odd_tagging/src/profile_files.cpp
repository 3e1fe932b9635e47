// ProfileFiles (profile_files.hpp): the three profile files, a batch at a time.
#include "railodd/odd/profile_files.hpp"

#include "profile_elements.hpp"
#include "profile_text.hpp"

#include "railodd/util/errors.hpp"

#include <system_error>

namespace railodd::odd {

ProfileFiles::ProfileFiles(std::ostream& json, std::ostream& geojson, std::ostream& csv, std::filesystem::path scratch)
    : json_(json), geojson_(geojson), csv_(csv), scratch_path_(std::move(scratch)),
      rows_(scratch_path_, std::ios::binary | std::ios::trunc), kinds_(std::make_unique<profile_elements::KindIndex>()) {
    if (!rows_) {
        throw OutputError(scratch_path_.string(), "cannot open for writing");
    }
}

ProfileFiles::~ProfileFiles() {
    rows_.close();
    std::error_code ec;
    std::filesystem::remove(scratch_path_, ec); // best effort: a destructor never throws
}

void ProfileFiles::begin(const OddProfile& head) {
    head_ = head;
    geojson_ << profile_text::geojson_head;
    line_.clear();
    profile_text::append_csv_header(line_);
    csv_ << line_;
}

void ProfileFiles::add(std::deque<TaggedElement>& batch) {
    for (const TaggedElement& e : batch) {
        const bool first = elements_++ == 0;
        line_.assign(first ? "  " : ",\n  ");
        profile_elements::append_row(line_, e, kinds_->of(e));
        rows_ << line_;
        line_.assign(first ? "" : ",\n");
        profile_text::append_feature(line_, e);
        geojson_ << line_;
        line_.clear();
        profile_text::append_csv_row(line_, field_, e);
        csv_ << line_;
    }
}

void ProfileFiles::end(const OddProfile& tail) {
    rows_ << (elements_ > 0 ? "\n" : "");
    rows_.close();
    if (!rows_) {
        throw OutputError(scratch_path_.string(), "write failed");
    }
    profile_text::write_json_head(head_, kinds_->list(), json_);
    std::ifstream rows(scratch_path_, std::ios::binary);
    if (!rows) {
        throw OutputError(scratch_path_.string(), "cannot be read back");
    }
    if (elements_ > 0) {
        json_ << rows.rdbuf();
    }
    profile_text::write_json_tail(tail, json_);
    geojson_ << (elements_ > 0 ? "\n" : "") << profile_text::geojson_tail;
}

} // namespace railodd::odd
